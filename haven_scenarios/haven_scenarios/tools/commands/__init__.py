"""The `haven` subcommands, one module per group; each registers its parsers with `add(sub)`."""
