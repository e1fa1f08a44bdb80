from dataclasses import dataclass


@dataclass(slots=True)
class Name:
    """A label for output and error messages."""

    value: str
