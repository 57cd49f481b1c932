"""``python -m surfmet`` runs the command-line interface."""

from surfmet.cli import main

raise SystemExit(main())
