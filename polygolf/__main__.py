"""`python -m polygolf`: the same as the `polygolf` command."""

import sys

from polygolf.game.cli import main

sys.exit(main())
