"""The processing report: HTML with figures like the paper's Fig. 7-9 and Tables 1-2."""

from clearfast_gis.report.html import ReportData, write_report

__all__ = ["ReportData", "write_report"]
