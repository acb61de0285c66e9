//! What the film network sees and what it predicts.
//!
//! Inputs. The isothermal, Newtonian line contact with Barus viscosity depends only on the
//! dimensionless groups `W, U, G` once the film is scaled by `R` (Dowson & Higginson 1966;
//! Moes 1992 reduces it further to `M, L`). The numerical solver of docs/physics.md §5.2 uses
//! Roelands viscosity and Dowson–Higginson density, which bring two more groups: the Roelands
//! index (through `ln η₀ + 9.67` and `α p₀`) and the pressure level `p_h/p₀`, `p_h` in Pa for
//! the density law (through `E'` once `W` is given). Hence two input sets:
//! [`InputSet::Wug`] = (ln W, ln U, ln G) and [`InputSet::WugEtaModulus`] = (ln W, ln U, ln G,
//! ln η₀, E'/GPa). Which one the data needs is measured (`bearing train --inputs …`).
//!
//! The point contact (docs/point_contact.md) with Barus viscosity and an incompressible
//! lubricant depends on Moes' groups M = W(2U)^−¾, L = G(2U)^¼ and the ellipticity k once the
//! film is scaled (Nijenbanning, Venner & Moes 1994): [`InputSet::Mlk`] = (ln M, ln L, ln k).
//! Roelands viscosity and Dowson–Higginson density add the groups the line contact adds, and G
//! is needed to separate α from E′: [`InputSet::MlkGEtaModulus`] = (ln M, ln L, ln k, ln G,
//! ln η₀, E′/GPa), which determines the point case up to its scale.
//!
//! Targets. [`TargetForm::LogRatio`]: `ln(h_c/h_reg,c)` and `ln(h_min/h_reg,min)`, ratios to
//! the contact's regression formulas (line: Dowson–Toyoda / Dowson–Higginson; point:
//! Hamrock–Dowson's central and minimum films) — strictly positive films, and the network
//! only learns the regression's error. [`TargetForm::LogHr`]: `ln(h/R)` (point: R_x).
//! [`TargetForm::Direct`]: `h` in µm, the unconstrained baseline (can go negative).

use bearing_ehl::point::formulas::{hamrock_dowson_central_film_m, hamrock_dowson_min_film_m};
use bearing_ehl::point::PointContactCase;
use serde::{Deserialize, Serialize};

use crate::dataset::formulas::{dowson_higginson_minimum, dowson_toyoda_central};
use crate::dataset::ContactCase;

/// A contact a film network is trained on: its features, its regression films (the
/// log-ratio target's reference) and its length scale (the log-h/R target's).
pub trait FilmCase: Clone + Send + Sync {
    /// The input sets of this contact, the default (`bearing train`'s) first.
    const INPUT_SETS: &'static [InputSet];
    /// The features of `set`; `set.len()` NaNs for a set of the other contact (which
    /// [`crate::ann::pipeline::train_model`] refuses before training).
    fn features(&self, set: InputSet) -> Vec<f64>;
    /// `(h_c, h_min)` of the contact's regression formulas, m.
    fn regression_films_m(&self) -> (f64, f64);
    /// The length the films are scaled by (R, or R_x), m.
    fn film_scale_m(&self) -> f64;
}

impl FilmCase for ContactCase {
    const INPUT_SETS: &'static [InputSet] = &[InputSet::Wug, InputSet::WugEtaModulus];

    fn features(&self, set: InputSet) -> Vec<f64> {
        let (w, u, g) = self.dimensionless();
        match set {
            InputSet::Wug => vec![w.ln(), u.ln(), g.ln()],
            InputSet::WugEtaModulus => vec![
                w.ln(),
                u.ln(),
                g.ln(),
                self.viscosity_pa_s.ln(),
                self.reduced_modulus_pa * 1e-9,
            ],
            InputSet::Mlk | InputSet::MlkGEtaModulus => vec![f64::NAN; set.len()],
        }
    }

    fn regression_films_m(&self) -> (f64, f64) {
        let (dt, dh) = regression_films_over_r(self);
        (dt * self.reduced_radius_m, dh * self.reduced_radius_m)
    }

    fn film_scale_m(&self) -> f64 {
        self.reduced_radius_m
    }
}

impl FilmCase for PointContactCase {
    const INPUT_SETS: &'static [InputSet] = &[InputSet::MlkGEtaModulus, InputSet::Mlk];

    fn features(&self, set: InputSet) -> Vec<f64> {
        let mlk = [
            self.moes_m().ln(),
            self.moes_l().ln(),
            self.hertz().ellipticity.ln(),
        ];
        match set {
            InputSet::Mlk => mlk.to_vec(),
            InputSet::MlkGEtaModulus => {
                let mut f = mlk.to_vec();
                f.push(self.material_parameter().ln());
                f.push(self.viscosity_pa_s.ln());
                f.push(self.reduced_modulus_pa * 1e-9);
                f
            }
            InputSet::Wug | InputSet::WugEtaModulus => vec![f64::NAN; set.len()],
        }
    }

    fn regression_films_m(&self) -> (f64, f64) {
        (
            hamrock_dowson_central_film_m(self),
            hamrock_dowson_min_film_m(self),
        )
    }

    fn film_scale_m(&self) -> f64 {
        self.radius_x_m
    }
}

/// Network input set (see the module doc).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "kebab-case")]
pub enum InputSet {
    /// (ln W, ln U, ln G).
    Wug,
    /// (ln W, ln U, ln G, ln η₀, E' in GPa).
    WugEtaModulus,
    /// Point contact: (ln M, ln L, ln k).
    Mlk,
    /// Point contact: (ln M, ln L, ln k, ln G, ln η₀, E′ in GPa).
    MlkGEtaModulus,
}

impl InputSet {
    /// Number of inputs.
    pub fn len(self) -> usize {
        match self {
            InputSet::Wug | InputSet::Mlk => 3,
            InputSet::WugEtaModulus => 5,
            InputSet::MlkGEtaModulus => 6,
        }
    }

    /// Never empty (clippy's `len` convention).
    pub fn is_empty(self) -> bool {
        false
    }

    /// The features of a case.
    pub fn features<C: FilmCase>(self, case: &C) -> Vec<f64> {
        case.features(self)
    }
}

/// Network output form (see the module doc).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "kebab-case")]
pub enum TargetForm {
    /// ln(h_c/h_DT), ln(h_min/h_DH).
    LogRatio,
    /// ln(h_c/R), ln(h_min/R).
    LogHr,
    /// h_c, h_min in µm.
    Direct,
}

/// `(h_DT/R, h_DH/R)`: the regression films of a case, scaled by R.
pub fn regression_films_over_r(case: &ContactCase) -> (f64, f64) {
    let (w, u, g) = case.dimensionless();
    (
        dowson_toyoda_central(w, u, g),
        dowson_higginson_minimum(w, u, g),
    )
}

impl TargetForm {
    /// Targets `[central, minimum]` from films (m).
    pub fn encode<C: FilmCase>(self, case: &C, films: (f64, f64)) -> [f64; 2] {
        let r = case.film_scale_m();
        match self {
            TargetForm::LogRatio => {
                let (c, m) = case.regression_films_m();
                [(films.0 / c).ln(), (films.1 / m).ln()]
            }
            TargetForm::LogHr => [(films.0 / r).ln(), (films.1 / r).ln()],
            TargetForm::Direct => [films.0 * 1e6, films.1 * 1e6],
        }
    }

    /// Films (m) from targets.
    pub fn decode<C: FilmCase>(self, case: &C, t: [f64; 2]) -> (f64, f64) {
        let r = case.film_scale_m();
        match self {
            TargetForm::LogRatio => {
                let (c, m) = case.regression_films_m();
                (c * t[0].exp(), m * t[1].exp())
            }
            TargetForm::LogHr => (r * t[0].exp(), r * t[1].exp()),
            TargetForm::Direct => (t[0] * 1e-6, t[1] * 1e-6),
        }
    }
}

/// Affine map of each column from `[min, max]` to `[−1, 1]`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Normaliser {
    /// Column minima.
    pub min: Vec<f64>,
    /// Column maxima.
    pub max: Vec<f64>,
}

impl Normaliser {
    /// Fit to the rows (a constant column gets a unit half-range).
    pub fn fit(rows: &[Vec<f64>]) -> Self {
        let dims = rows.first().map_or(0, Vec::len);
        let mut min = vec![f64::INFINITY; dims];
        let mut max = vec![f64::NEG_INFINITY; dims];
        for r in rows {
            for ((lo, hi), v) in min.iter_mut().zip(max.iter_mut()).zip(r) {
                *lo = lo.min(*v);
                *hi = hi.max(*v);
            }
        }
        for (lo, hi) in min.iter_mut().zip(max.iter_mut()) {
            if *hi <= *lo {
                *hi = *lo + 1.0;
                *lo -= 1.0;
            }
        }
        Self { min, max }
    }

    /// Fit, then widen each range by `margin` × range on both sides, so inputs slightly outside
    /// the training set (validation, test, the domain's corners) still map inside [−1, 1] —
    /// the integer network saturates its inputs there.
    pub fn fit_with_margin(rows: &[Vec<f64>], margin: f64) -> Self {
        let mut n = Self::fit(rows);
        for (lo, hi) in n.min.iter_mut().zip(n.max.iter_mut()) {
            let pad = margin * (*hi - *lo);
            *lo -= pad;
            *hi += pad;
        }
        n
    }

    /// To `[−1, 1]`.
    pub fn forward(&self, x: &[f64]) -> Vec<f64> {
        x.iter()
            .zip(self.min.iter().zip(&self.max))
            .map(|(v, (lo, hi))| 2.0 * (v - lo) / (hi - lo) - 1.0)
            .collect()
    }

    /// From `[−1, 1]`.
    pub fn inverse(&self, y: &[f64]) -> Vec<f64> {
        y.iter()
            .zip(self.min.iter().zip(&self.max))
            .map(|(v, (lo, hi))| lo + 0.5 * (v + 1.0) * (hi - lo))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn case() -> ContactCase {
        ContactCase {
            load_n: 1000.0,
            entrainment_speed_m_s: 5.0,
            reduced_radius_m: 5e-3,
            reduced_modulus_pa: 230e9,
            pressure_viscosity_pa_inv: 2e-8,
            viscosity_pa_s: 0.02,
            length_m: 10e-3,
        }
    }

    /// decode ∘ encode = identity for every target form (the inverse is exact algebra).
    #[test]
    fn targets_round_trip() {
        for form in [TargetForm::LogRatio, TargetForm::LogHr, TargetForm::Direct] {
            let films = (2.1e-7, 1.6e-7);
            let back = form.decode(&case(), form.encode(&case(), films));
            assert!(
                (back.0 / films.0 - 1.0).abs() < 1e-12 && (back.1 / films.1 - 1.0).abs() < 1e-12
            );
        }
    }

    /// Normalisation maps the fitted extremes onto ±1 and inverts exactly.
    #[test]
    fn normaliser_maps_extremes_to_unit() {
        let rows = vec![vec![1.0, -5.0], vec![3.0, 5.0], vec![2.0, 0.0]];
        let n = Normaliser::fit(&rows);
        assert_eq!(n.forward(&rows[0]), vec![-1.0, -1.0]);
        assert_eq!(n.forward(&rows[1]), vec![1.0, 1.0]);
        assert_eq!(n.inverse(&n.forward(&rows[2])), rows[2]);
    }
}
