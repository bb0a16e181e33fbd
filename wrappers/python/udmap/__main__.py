"""``python3 -m udmap``: the command line (see udmap.cli)."""
import sys

from .cli import main

sys.exit(main())
