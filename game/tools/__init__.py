"""Tooling beside the command line: the accuracy report, `explain`, `validate`."""
