"""Content loading: YAML with line numbers, typed models, one-line errors. No golf rules."""
