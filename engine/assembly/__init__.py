"""Assembly: the one stage table, the world spec, the one assembler, and the running simulation."""
