"""PolyGolf engine: rigid polygons in an esper pipeline. Nothing here imports arcade."""
