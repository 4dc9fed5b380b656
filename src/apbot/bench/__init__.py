"""Benchmark suites, runners, metrics and reports."""
