"""Shipped content (YAML): holes, courses, tile library, themes, scenes. Package data."""
