"""Product writers: COG mosaics, GeoPackage layers with default styles, products manifest,
mine-action export.

Every writer is atomic (temporary name, then rename) and validates what it writes against the
JSON Schemas in ``clearfast_gis/schemas``.
"""

from clearfast_gis.export.cog import (
    SCAN_TIME_TAG,
    Mosaic,
    band_description,
    read_mosaic,
    write_cog,
)
from clearfast_gis.export.geopackage import add_layer_styles, read_layer_styles, write_geopackage
from clearfast_gis.export.layout import mosaic_name
from clearfast_gis.export.manifest import (
    read_products_manifest,
    sha256_file,
    write_products_manifest,
)
from clearfast_gis.export.mine_action import (
    MINE_ACTION_FIELDS,
    MineActionExport,
    export_mine_action,
    mine_action_table,
    stable_ids,
)
from clearfast_gis.export.styles import default_styles, mine_action_style, mosaic_style
from clearfast_gis.export.suspects import (
    SUSPECT_COLUMNS,
    contrast_series_text,
    parse_contrast_series,
    suspects_frame,
)

__all__ = [
    "MINE_ACTION_FIELDS", "SCAN_TIME_TAG", "SUSPECT_COLUMNS", "MineActionExport", "Mosaic",
    "add_layer_styles", "band_description", "contrast_series_text", "default_styles",
    "export_mine_action", "mine_action_style", "mine_action_table", "mosaic_name",
    "mosaic_style", "parse_contrast_series", "read_layer_styles", "read_mosaic",
    "read_products_manifest", "sha256_file", "stable_ids", "suspects_frame", "write_cog",
    "write_geopackage", "write_products_manifest",
]
