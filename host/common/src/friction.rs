//! The core's friction model (docs/physics.md §8) on the host, from roller loads the caller
//! gives and films the host computes: for a bearing whose step has no film (the dry model) and
//! for measuring the core's load-sharing shortcut against a re-solved film.
//!
//! Films come from the regression formulas (docs/physics.md §5.1, the fallback of every core
//! film model) with the bearing's high-speed corrections (§5.4) applied as the film table
//! applies them.

use bearing_core::film::corrections::corrected_film_m;
use bearing_core::film::martin_film_m;
use bearing_core::friction::{BearingFriction, ContactFriction, FrictionSums, Prepared};
use bearing_core::{BearingParams, ContactInput, FilmModel, Regression};

/// Smallest load (N) at which a film is evaluated: an unloaded roller's contact is treated as
/// carrying 1 mN, as the core's rolling-resistance law floors it (docs/physics.md §8.3).
const MIN_FILM_LOAD_N: f32 = 1.0e-3;
/// The re-solved film is accepted when it moves by less than this fraction in one iteration.
const FIXED_POINT_TOLERANCE: f32 = 1.0e-5;
/// Iterations allowed for the re-solved film.
const MAX_FIXED_POINT_ITERATIONS: usize = 50;

/// How the film of a contact shares its load with the asperities (docs/physics.md §8.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LoadSharing {
    /// As the core: the film of the whole load Q, the asperity load W_a evaluated at it.
    WholeLoadFilm,
    /// The film re-solved for the load the film carries, h = h(Q − W_a(h)), by fixed-point
    /// iteration.
    Resolved,
}

/// The central film (m) of `input` from the regression formulas, corrected by the bearing's
/// film corrections (off: the regression's film as it is).
pub fn regression_film_m(params: &BearingParams, input: &ContactInput) -> f32 {
    let input = ContactInput {
        load_n: input.load_n.max(MIN_FILM_LOAD_N),
        ..*input
    };
    let h = Regression.film(&input).central_m;
    let corrections = params.film_corrections();
    if corrections.is_off() {
        return h;
    }
    let factor = corrections.factors(&input, h).product();
    corrected_film_m(h, martin_film_m(&input), factor)
}

/// One contact's friction with the film it was evaluated at.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SharedContact {
    /// The friction (λ, W_a and the forces).
    pub friction: ContactFriction,
    /// The central film used (m).
    pub central_film_m: f32,
    /// Fixed-point iterations (0 for [`LoadSharing::WholeLoadFilm`]).
    pub iterations: usize,
}

/// The friction of `input` (its load `input.load_n`) with the film of
/// [`regression_film_m`], shared with the asperities as `sharing` says.
pub fn contact_friction(
    params: &BearingParams,
    prepared: &Prepared,
    input: &ContactInput,
    sharing: LoadSharing,
) -> SharedContact {
    let mut film = regression_film_m(params, input);
    let mut friction = prepared.contact(input, film);
    let mut iterations = 0;
    if sharing == LoadSharing::Resolved {
        while iterations < MAX_FIXED_POINT_ITERATIONS {
            iterations += 1;
            let film_load = ContactInput {
                load_n: input.load_n - friction.asperity_load_n,
                ..*input
            };
            let next = regression_film_m(params, &film_load);
            let moved = (next - film).abs();
            film = next;
            friction = prepared.contact(input, film);
            if moved <= FIXED_POINT_TOLERANCE * film {
                break;
            }
        }
    }
    SharedContact {
        friction,
        central_film_m: film,
        iterations,
    }
}

/// A bearing's friction from its roller loads.
#[derive(Clone, Debug, PartialEq)]
pub struct BearingFrictionAtLoads {
    /// Torque, power and split.
    pub bearing: BearingFriction,
    /// [inner, outer] contact of every roller.
    pub contacts: Vec<[SharedContact; 2]>,
}

impl BearingFrictionAtLoads {
    /// Σ W_a over every contact (N).
    pub fn asperity_load_n(&self) -> f32 {
        self.contacts
            .iter()
            .flatten()
            .map(|c| c.friction.asperity_load_n)
            .sum()
    }

    /// [λ_in, λ_out] of the most loaded roller (by inner-contact load); None without rollers.
    pub fn lambda_of_most_loaded(&self) -> Option<[f32; 2]> {
        self.contacts
            .iter()
            .max_by(|a, b| a[0].friction.load_n.total_cmp(&b[0].friction.load_n))
            .map(|[i, o]| [i.friction.lambda, o.friction.lambda])
    }
}

/// The friction of a bearing whose rollers carry `roller_loads_n` on their inner contacts (N)
/// and that plus `centrifugal_force_n` on their outer ones, at shaft speed ω (rad/s), with
/// films from [`regression_film_m`] at those loads: the core's friction pass
/// (docs/physics.md §8.4) with host films.
pub fn bearing_friction_at_loads(
    params: &BearingParams,
    roller_loads_n: &[f32],
    centrifugal_force_n: f32,
    shaft_speed_rad_s: f32,
    sharing: LoadSharing,
) -> BearingFrictionAtLoads {
    let templates = [false, true].map(|outer| params.contact_input(outer, 0.0, shaft_speed_rad_s));
    let prepared = templates.map(|t| Prepared::new(params.friction(), &t));
    let mut sums = FrictionSums::default();
    let contacts: Vec<[SharedContact; 2]> = roller_loads_n
        .iter()
        .map(|&load| {
            let loads = [load, load + centrifugal_force_n];
            let pair: [SharedContact; 2] = std::array::from_fn(|k| {
                let input = ContactInput {
                    load_n: loads[k],
                    ..templates[k]
                };
                contact_friction(params, &prepared[k], &input, sharing)
            });
            sums.add(&pair[0].friction);
            sums.add(&pair[1].friction);
            pair
        })
        .collect();
    let bearing = sums.bearing(
        params.geometry().entrainment_speed_m_s(1.0),
        params.friction().slide_to_roll_ratio(),
        shaft_speed_rad_s,
    );
    BearingFrictionAtLoads { bearing, contacts }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn nu205() -> BearingParams {
        let path =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../configs/nu205.toml");
        crate::config::BearingConfig::load(&path).unwrap().1
    }

    /// The re-solved film satisfies its own equation h = h(Q − W_a(h)) and lies above the
    /// whole-load film (the film carries less load); with asperities carrying nothing
    /// (thick film) the two coincide.
    #[test]
    fn resolved_film_is_the_fixed_point_and_thicker() {
        let params = nu205();
        for (rpm, load) in [(20.0_f32, 400.0_f32), (200.0, 400.0), (5000.0, 400.0)] {
            let speed = rpm * std::f32::consts::PI / 30.0;
            let input = params.contact_input(false, load, speed);
            let prepared = Prepared::new(params.friction(), &input);
            let whole = contact_friction(&params, &prepared, &input, LoadSharing::WholeLoadFilm);
            let resolved = contact_friction(&params, &prepared, &input, LoadSharing::Resolved);
            let film_load = ContactInput {
                load_n: load - resolved.friction.asperity_load_n,
                ..input
            };
            let h = regression_film_m(&params, &film_load);
            assert!(
                (h / resolved.central_film_m - 1.0).abs() < 1e-4,
                "{rpm} rpm: {h} vs {}",
                resolved.central_film_m
            );
            assert!(resolved.central_film_m >= whole.central_film_m);
            assert!(resolved.friction.asperity_load_n <= whole.friction.asperity_load_n);
            if whole.friction.asperity_load_n == 0.0 {
                assert_eq!(resolved.central_film_m, whole.central_film_m);
            }
        }
    }

    /// Without corrections the film is the regression's; the bearing sums equal the core's
    /// pass at the same films (its [`FrictionSums::bearing`]).
    #[test]
    fn uncorrected_film_is_the_regression_and_sums_add_up() {
        let params = nu205();
        let speed = 300.0;
        let input = params.contact_input(false, 500.0, speed);
        assert_eq!(
            regression_film_m(&params, &input),
            Regression.film(&input).central_m
        );
        let r = bearing_friction_at_loads(
            &params,
            &[500.0, 200.0, 0.0],
            0.0,
            speed,
            LoadSharing::WholeLoadFilm,
        );
        let split: f32 = r.bearing.power_loss_split_w.iter().sum();
        assert!((split / r.bearing.power_loss_w - 1.0).abs() < 1e-5);
        assert!((r.bearing.power_loss_w / (r.bearing.torque_nm * speed) - 1.0).abs() < 1e-5);
        assert_eq!(r.contacts.len(), 3);
    }
}
