"""``python -m jkrcyl``: the command line of :mod:`jkrcyl.cli`."""
import sys

from .cli import main

sys.exit(main())
