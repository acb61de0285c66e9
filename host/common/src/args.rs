//! Command-line parsing shared by `bearing` and `hil-sim`.

use clap::{Command, FromArgMatches};

/// Parses the command line into `T` like `T::parse()`, with one difference: in every
/// subcommand a value that looks like a negative number (`--settle -1`, `--whirl-hz -3e2`) is a
/// value, not an unknown flag, so the range check of its flag can name it and say what is
/// allowed. No flag of either program is spelled as a number, so nothing becomes ambiguous.
pub fn parse<T: clap::CommandFactory + FromArgMatches>() -> T {
    let matches = with_negative_numbers(T::command()).get_matches();
    T::from_arg_matches(&matches).unwrap_or_else(|e| e.exit())
}

fn with_negative_numbers(command: Command) -> Command {
    command
        .allow_negative_numbers(true)
        .mut_subcommands(with_negative_numbers)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(clap::Parser, Debug)]
    struct Top {
        #[command(subcommand)]
        command: Sub,
    }

    #[derive(clap::Subcommand, Debug)]
    enum Sub {
        Run {
            #[arg(long)]
            settle: f64,
        },
    }

    #[test]
    fn a_negative_number_in_a_subcommand_is_a_value() {
        use clap::CommandFactory as _;
        let argv = ["top", "run", "--settle", "-1"];
        assert!(Top::command().try_get_matches_from(argv).is_err());
        let matches = with_negative_numbers(Top::command())
            .try_get_matches_from(argv)
            .unwrap();
        let Sub::Run { settle } = Top::from_arg_matches(&matches).unwrap().command;
        assert_eq!(settle, -1.0);
    }
}
