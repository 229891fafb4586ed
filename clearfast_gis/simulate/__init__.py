"""The survey digital twin: a complete simulated survey folder with its ground truth.

``simulate_survey(out_dir, preset("demo"), seed=0)`` writes a folder that ``clearfast
validate`` accepts, plus ``truth/`` (objects, true apparent temperature per scan, true poses).
"""

from clearfast_gis.simulate.config import PRESETS, Band, ObjectCounts, SimConfig, preset
from clearfast_gis.simulate.objects import KINDS, SceneObject, draw_objects
from clearfast_gis.simulate.run import SimulationResult, simulate_survey
from clearfast_gis.simulate.scenario import Scenario, load_scenario, parse_scenario

__all__ = ["KINDS", "PRESETS", "Band", "ObjectCounts", "Scenario", "SceneObject", "SimConfig",
           "SimulationResult", "draw_objects", "load_scenario", "parse_scenario", "preset",
           "simulate_survey"]
