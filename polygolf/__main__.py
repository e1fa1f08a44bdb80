"""`python -m polygolf`: the same as the `polygolf` command."""

import sys

from polygolf.game.cli import main

if __name__ == "__main__":  # as every main module of a program that spawns processes
    sys.exit(main())
