"""``python -m plans``: the pure commands (no ``draw``); Ctrl-C while loading stops with 130."""

try:
    from plans.cli import main
except KeyboardInterrupt:
    raise SystemExit(130) from None

raise SystemExit(main())
