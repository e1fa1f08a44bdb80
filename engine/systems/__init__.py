"""esper processors, one concern a file. Each is thin: fetch components, call kernels, write back."""
