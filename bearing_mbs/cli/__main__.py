"""``python -m bearing_mbs.cli``: the ``bearing-mbs`` command."""

import sys

from bearing_mbs.cli import main

sys.exit(main())
