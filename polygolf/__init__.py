"""PolyGolf: mini golf with a polygon for a ball.

The repository keeps the product card's folders (engine/, game/, content/) at its top; the installed
distribution maps them under this one import package (`polygolf.engine`, `polygolf.game`,
`polygolf.content`), so nothing with a generic name lands at the top of site-packages.
"""

from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("polygolf")
except PackageNotFoundError:  # running from a source tree that was never installed
    __version__ = "0+unknown"
