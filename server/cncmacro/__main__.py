"""``python -m cncmacro``: the same as the ``cncmacro`` command."""

import sys

from .cli.main import main

sys.exit(main())
