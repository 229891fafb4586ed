"""Multi-scale snapshot detector: the morphological chain at a ladder of object sizes.

One D1 cannot fit objects from 13 to 500 pixels across (a snapshot taken from 0.4 to 10 m),
so the chain of :func:`clearfast_gis.detection.detector.detect_anomalies` (top-hat or
bottom-hat by reconstruction, stretch and threshold, opening by reconstruction) runs once per
object diameter ``d`` of a ladder. Each scale works on the image shrunk so that ``d`` spans
about ``work_px`` pixels (block averaging), smoothed by a Gaussian of ``smooth_ratio * d``, with
``D1 = d1_ratio * d`` and ``D2 = d2_ratio * d``; the cost is therefore about the same at every
scale and falls for the large ones. A scale keeps the blobs whose equivalent diameter lies in
``[size_band[0] d, size_band[1] d]`` (its own size range), and blobs found at several scales are
merged by non-maximum suppression (best score first; a blob whose centroid lies inside a kept
blob's equivalent disk, or whose disk holds a kept centroid, is dropped).

Score of a candidate (scale-normalised, all terms dimensionless):
``|contrast| / sigma_ring`` (centre mean minus the mean of a ring of 1.5-2.5 equivalent radii,
over the ring's standard deviation, both on the working image) times ``0.5 + 0.5 circularity``
times ``fill ** fill_power`` where ``fill`` is the fraction of the blob's equivalent disk it
covers at its own scale... see :func:`candidate_score` for the exact form.
"""
