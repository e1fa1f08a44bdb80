"""PolyGolf front end: the `polygolf` command and the arcade screens. Physics lives in engine/."""
