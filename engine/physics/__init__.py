"""Physics kernels: pure functions and plain data over floats. No esper, no YAML, no golf."""
