"""Scoring products against a simulated survey's ground truth (never used by the chain)."""

from clearfast_gis.evaluation.honesty import MineStatus, honest, mine_statuses
from clearfast_gis.evaluation.truth import (
    PlacementScore,
    TruthScore,
    placement_errors,
    read_true_poses,
    read_truth_objects,
    score_against_truth,
)

__all__ = ["MineStatus", "PlacementScore", "TruthScore", "honest", "mine_statuses",
           "placement_errors", "read_true_poses", "read_truth_objects", "score_against_truth"]
