//! The film model of a bearing, chosen once when the bearing is built.

use core::fmt;
use core::str::FromStr;

/// Which film model a [`Bearing`](crate::Bearing) steps with.
///
/// The bearing's film table is filled from this model and from no other, so the table and the
/// model cannot disagree. Each variant is a concrete type inside the step (static dispatch: the
/// film model is inlined into the film table's renewal).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(rename_all = "snake_case")
)]
pub enum FilmKind {
    /// The integer (quantised) neural network, with its regression fallback.
    Int,
    /// The f32 neural network, with its regression fallback.
    F32,
    /// The regression formulas (Dowson–Toyoda / Dowson–Higginson blended with Martin's film).
    Regression,
    /// No film (h ≡ 0): the dry slicing contact of today's multi-body practice.
    Dry,
}

impl FilmKind {
    /// Every kind, in the order of [`FilmKind::name`]'s list.
    pub const ALL: [FilmKind; 4] = [
        FilmKind::Int,
        FilmKind::F32,
        FilmKind::Regression,
        FilmKind::Dry,
    ];

    /// The name on command lines, in configuration files and in reports:
    /// `int`, `f32`, `regression`, `dry`.
    ///
    /// ```
    /// use bearing_core::FilmKind;
    /// assert_eq!(FilmKind::Int.name(), "int");
    /// assert_eq!(FilmKind::from_name(b" dry\n"), Some(FilmKind::Dry));
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            FilmKind::Int => "int",
            FilmKind::F32 => "f32",
            FilmKind::Regression => "regression",
            FilmKind::Dry => "dry",
        }
    }

    /// The kind of a name (surrounding ASCII whitespace ignored), `None` for any other text.
    pub fn from_name(name: &[u8]) -> Option<FilmKind> {
        let trimmed = name.trim_ascii();
        Self::ALL
            .into_iter()
            .find(|kind| kind.name().as_bytes() == trimmed)
    }
}

impl fmt::Display for FilmKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A text that names no film model.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct UnknownFilmKind;

impl fmt::Display for UnknownFilmKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("unknown film model: expected one of int, f32, regression, dry")
    }
}

impl core::error::Error for UnknownFilmKind {}

impl FromStr for FilmKind {
    type Err = UnknownFilmKind;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Self::from_name(s.as_bytes()).ok_or(UnknownFilmKind)
    }
}
