"""``python -m scanconv``."""

import sys

from .cli import main

sys.exit(main())
