"""CLEARFAST QGIS plugin: open survey products and run the clearfast toolkit from Processing."""


def classFactory(iface=None):
    """QGIS entry point; ``iface`` is None under ``qgis_process`` and in tests."""
    from .plugin import ClearfastPlugin

    return ClearfastPlugin(iface)
