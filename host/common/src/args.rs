//! Command-line parsing shared by `bearing` and `hil-sim`.

use clap::{Command, FromArgMatches};

/// Parses the command line into `T` like `T::parse()`, with one difference: in every
/// subcommand a value that looks like a negative number (`--settle -1`, `--whirl-hz -3e2`) is a
/// value, not an unknown flag, so the range check of its flag can name it and say what is
/// allowed. No flag of either program is spelled as a number, so nothing becomes ambiguous.
/// Clap counts only digits as a number (`-1`, `-3e2`), so a floating-point flag (f64 or f32
/// value) also takes any value that starts with a hyphen (`--load -inf`, `-nan`): its parser
/// then names the flag and its range instead of "unexpected argument '-i'".
pub fn parse<T: clap::CommandFactory + FromArgMatches>() -> T {
    let matches = with_negative_numbers(T::command()).get_matches();
    T::from_arg_matches(&matches).unwrap_or_else(|e| e.exit())
}

fn with_negative_numbers(command: Command) -> Command {
    let floats: Vec<clap::Id> = command
        .get_arguments()
        .filter(|a| a.get_action().takes_values() && takes_a_float(a))
        .map(|a| a.get_id().clone())
        .collect();
    floats
        .iter()
        .fold(command, |c, id| {
            c.mut_arg(id, |a| a.allow_hyphen_values(true))
        })
        .allow_negative_numbers(true)
        .mut_subcommands(with_negative_numbers)
}

/// Whether the argument's values parse to a floating-point number.
fn takes_a_float(arg: &clap::Arg) -> bool {
    let id = arg.get_value_parser().type_id();
    id == std::any::TypeId::of::<f64>() || id == std::any::TypeId::of::<f32>()
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

    #[test]
    fn minus_infinity_is_a_value_of_a_float_flag() {
        use clap::CommandFactory as _;
        let argv = ["top", "run", "--settle", "-inf"];
        assert!(Top::command().try_get_matches_from(argv).is_err());
        let matches = with_negative_numbers(Top::command())
            .try_get_matches_from(argv)
            .unwrap();
        let Sub::Run { settle } = Top::from_arg_matches(&matches).unwrap().command;
        assert_eq!(settle, f64::NEG_INFINITY);
    }
}
