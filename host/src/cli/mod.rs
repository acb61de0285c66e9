//! One module per `bearing` subcommand.
