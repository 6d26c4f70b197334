"""``python -m jkrcyl.cli``: the same as ``jkrcyl`` and ``python -m jkrcyl``."""
import sys

from . import main

sys.exit(main())
