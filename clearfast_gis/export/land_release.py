"""Land-release records of the mine-action export: the surveyed area and the suspected-hazard
polygon proposals (IMAS 07.11), with their fields, in WGS84.

The evidence points are :mod:`clearfast_gis.export.mine_action`'s; the clustering and the
geometry checks :mod:`clearfast_gis.export.hazard_areas`'.
"""

from __future__ import annotations

import numpy as np

from clearfast_gis.export.mine_action import EVIDENCE, METHOD, survey_code

HAZARD_CLASS = "suspected hazardous area (proposed)"
SURVEY_RESULT = "surveyed by stand-off thermal IR; not cleared"

HAZARD_FIELDS: dict[str, str] = {
    "imsma_id": "Stable text id CF-<SURVEY>-H<NN>",
    "imsma_links": "Empty: links are made in IMSMA Core",
    "survey_id": "Survey id (products.json)",
    "survey_date_utc": "Survey start, ISO 8601 UTC",
    "land_class": f'Always "{HAZARD_CLASS}"',
    "method": f'Always "{METHOD}"',
    "evidence": f'Always "{EVIDENCE}"',
    "organisation": "Surveying organisation",
    "buffer_m": "Radius of the disc around each mine indication, metres",
    "n_indications": "Mine indications inside",
    "evidence_ids": "imsma_id of those indications, comma-separated",
    "area_m2": "Area in the survey's UTM CRS, square metres",
    "centroid_lat_deg": "Centroid latitude, WGS84 decimal degrees",
    "centroid_lon_deg": "Centroid longitude, WGS84 decimal degrees",
    "wkt": "Polygon in WGS84 (lon lat), WKT (CSV only)",
}
"""Columns of the hazard polygon proposals (layer and CSV)."""

AREA_FIELDS: dict[str, str] = {
    "imsma_id": "Stable text id CF-<SURVEY>-SA",
    "imsma_links": "Empty: links are made in IMSMA Core",
    "survey_id": "Survey id (products.json)",
    "survey_start_utc": "Survey start, ISO 8601 UTC",
    "survey_end_utc": "Survey end, ISO 8601 UTC",
    "method": f'Always "{METHOD}"',
    "organisation": "Surveying organisation",
    "result": f'Always "{SURVEY_RESULT}"',
    "area_m2": "Area in the survey's UTM CRS, square metres",
    "n_suspects": "Suspects found",
    "n_indications": "Mine indications among them",
    "n_hazard_proposals": "Hazard polygons proposed",
    "utm_epsg": "EPSG code of the survey's UTM CRS",
    "wkt": "Polygon in WGS84 (lon lat), WKT (CSV only)",
}
"""Columns of the surveyed-area record (layer and CSV)."""

WGS84_GRID_DEG = 1e-8
"""Coordinates of the exported polygons are rounded to this grid (about 1 mm)."""


def _to_wgs84(geoms, epsg: int):
    """UTM polygons to WGS84, on a :data:`WGS84_GRID_DEG` grid, without repeated vertices."""
    import shapely
    from pyproj import Transformer

    from clearfast_gis.export.hazard_areas import clean_polygon

    fwd = Transformer.from_crs(int(epsg), 4326, always_xy=True)
    out = []
    for g in geoms:
        ll = shapely.transform(g, lambda xy: np.column_stack(fwd.transform(xy[:, 0], xy[:, 1])))
        out.append(clean_polygon(shapely.set_precision(ll, WGS84_GRID_DEG)))
    return out


def hazard_table(evidence, epsg: int, survey_id: str, organisation: str, buffer_m: float):
    """Hazard polygon proposals around the mine indications of ``evidence``.

    Sets ``hazard_ref`` of the evidence rows inside a proposal (in place).

    Returns
    -------
    (pandas.DataFrame, list of shapely.Polygon)
        Columns :data:`HAZARD_FIELDS` and the polygons in WGS84, one per proposal.
    """
    import pandas as pd
    import shapely

    from clearfast_gis.export.hazard_areas import hazard_clusters

    mine = np.flatnonzero(evidence["mine_indication"].to_numpy() == "yes")
    clusters = hazard_clusters(evidence["utm_easting_m"].to_numpy()[mine],
                               evidence["utm_northing_m"].to_numpy()[mine], buffer_m)
    code = survey_code(survey_id)
    rows, polys = [], _to_wgs84([poly for poly, _ in clusters], epsg)
    hazard_col = evidence.columns.get_loc("hazard_ref")
    for k, ((poly, members), ll) in enumerate(zip(clusters, polys, strict=True), start=1):
        hid = f"CF-{code}-H{k:02d}"
        idx = sorted(int(mine[m]) for m in members)
        evidence.iloc[idx, hazard_col] = hid
        centre = ll.centroid
        rows.append({
            "imsma_id": hid, "imsma_links": "", "survey_id": survey_id,
            "survey_date_utc": evidence["survey_date_utc"].iloc[0], "land_class": HAZARD_CLASS,
            "method": METHOD, "evidence": EVIDENCE, "organisation": organisation,
            "buffer_m": float(buffer_m), "n_indications": len(idx),
            "evidence_ids": ",".join(evidence["imsma_id"].iloc[idx]),
            "area_m2": float(poly.area), "centroid_lat_deg": centre.y,
            "centroid_lon_deg": centre.x, "wkt": shapely.to_wkt(ll, rounding_precision=8)})
    return pd.DataFrame(rows, columns=list(HAZARD_FIELDS)), polys


def surveyed_area_table(footprint_utm, epsg: int, survey_id: str, times_utc: tuple[str, str],
                        organisation: str, counts: tuple[int, int, int]):
    """The surveyed-area record: the survey footprint (one polygon, UTM in, WGS84 out).

    ``times_utc`` is the survey's (start, end), ISO 8601 UTC; ``counts`` the numbers of
    suspects, mine indications and hazard proposals.

    Returns
    -------
    (pandas.DataFrame, list of shapely geometry)
        Columns :data:`AREA_FIELDS`, one row, and its WGS84 polygon.
    """
    import pandas as pd
    import shapely

    area = shapely.union_all(list(footprint_utm))
    ll = _to_wgs84([area], epsg)
    n_suspects, n_indications, n_hazards = counts
    row = {"imsma_id": f"CF-{survey_code(survey_id)}-SA", "imsma_links": "",
           "survey_id": survey_id, "survey_start_utc": times_utc[0],
           "survey_end_utc": times_utc[1], "method": METHOD, "organisation": organisation,
           "result": SURVEY_RESULT, "area_m2": float(area.area), "n_suspects": n_suspects,
           "n_indications": n_indications, "n_hazard_proposals": n_hazards,
           "utm_epsg": int(epsg), "wkt": shapely.to_wkt(ll[0], rounding_precision=8)}
    return pd.DataFrame([row], columns=list(AREA_FIELDS)), ll
