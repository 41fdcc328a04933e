"""`python -m haven_scenarios`: the `haven` command."""

import sys

from haven_scenarios.tools.cli import main

sys.exit(main())
