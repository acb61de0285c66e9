//! The Moes stand-in target of the pipeline tests, and the closed-form film formulas the dataset
//! and the network use, which live with the solver they are checked against
//! ([`bearing_ehl::formulas`], docs/physics.md §5.1). All take the dimensionless groups of
//! docs/physics.md §1 (`W = w/(E'R)`, `U = η₀u_m/(E'R)`, `G = αE'`) and return `h/R`.

pub use bearing_ehl::formulas::{
    dowson_higginson_minimum, dowson_toyoda_central, moes_central, moes_parameters, MoesAsymptotes,
};

/// Minimum film of the Moes stand-in: the Moes central film scaled by the ratio of the
/// Dowson–Higginson minimum to the Dowson–Toyoda central film. Moes gives no minimum-film
/// formula; this keeps the stand-in smooth, positive and different from both regression
/// formulas, which is all a pipeline test needs. It is not a physical claim.
pub fn moes_minimum(w: f64, u: f64, g: f64) -> f64 {
    moes_central(w, u, g) * dowson_higginson_minimum(w, u, g) / dowson_toyoda_central(w, u, g)
}
