"""A stand-in for the ``clearfast`` command: emits ``--progress json`` lines like the toolkit.

Used to test the plugin's progress parsing and cancellation independently of the pipeline.
``FAKE_CLEARFAST_STEPS`` (default 5) steps of ``FAKE_CLEARFAST_STEP_S`` seconds (default
0.02); ``process``/``detect`` write a demo products folder (``-o`` or the PRODUCTS argument);
``options`` answers at once with no defaults; ``FAKE_CLEARFAST_PID_FILE`` receives the
process id; ``FAKE_CLEARFAST_FAIL`` makes it fail with
a one-line error.
"""

from __future__ import annotations

import json
import os
import sys
import time


def main(argv: list[str]) -> int:
    if argv[:1] == ["options"]:
        # answered at once, as the toolkit does: the plugin asks it before its first run, and
        # a test that cancels a long fake run must not wait for this query's fake steps
        print(json.dumps({"process": {}}), flush=True)
        return 0
    pid_file = os.environ.get("FAKE_CLEARFAST_PID_FILE")
    if pid_file:
        with open(pid_file, "w") as fh:
            fh.write(str(os.getpid()))
    steps = int(os.environ.get("FAKE_CLEARFAST_STEPS", "5"))
    step_s = float(os.environ.get("FAKE_CLEARFAST_STEP_S", "0.02"))
    print("fake clearfast starting", flush=True)
    print(json.dumps({"event": "start", "stage": "fake", "done": 0, "total": steps,
                      "fraction": 0.0}), flush=True)
    for i in range(1, steps + 1):
        time.sleep(step_s)
        print(json.dumps({"event": "progress", "stage": "fake", "done": i, "total": steps,
                          "fraction": i / steps}), flush=True)
    print(json.dumps({"event": "message", "stage": "fake", "message": "half-way note"}),
          flush=True)
    print(json.dumps({"event": "end", "stage": "fake", "done": steps, "total": steps,
                      "fraction": 1.0}), flush=True)
    if os.environ.get("FAKE_CLEARFAST_FAIL"):
        print("clearfast: error: survey.json: camera.resolution: expected 2 integers",
              file=sys.stderr)
        return 1
    if argv and argv[0] in ("process", "detect"):
        out = argv[argv.index("-o") + 1] if "-o" in argv else argv[1]
        if not os.path.isfile(os.path.join(out, "products.json")):
            from clearfast_gis.export.testing import make_demo_products

            make_demo_products(out, n_scans=3, pixel_size_m=0.1, figures=False)
        with open(os.path.join(out, "fake_args.json"), "w") as fh:
            json.dump(argv, fh)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
