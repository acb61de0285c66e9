//! Speed sweep (docs/physics.md §6.2): at each speed, run to steady state with the lubricated
//! bearings and again with dry ones, and keep the envelopes. Speeds run in parallel (rayon) with
//! a progress bar; each run owns fresh bearing models.

use rayon::prelude::*;

use crate::analysis::operating::{build_bearings, linearise, operating_modes, OperatingError};
use crate::analysis::simulate::{run, Envelope, RunError, RunResult, RunSettings};
use crate::analysis::spectrum::amplitude_spectrum;
use crate::analysis::statics::equilibrium;
use crate::bearing::{BearingFriction, BearingSpec, FilmKind};
use crate::model::RotorModel;

/// Natural frequencies kept per speed and side (the lowest, with the bearings linearised).
pub const SWEEP_MODES: usize = 4;

/// The sweep speeds of docs/physics.md §6.2: 1000 → 21 000 rpm every 1000 rpm, plus every 250 rpm
/// from 12 000 to 14 000 rpm.
pub fn hub_motor_speeds_rpm() -> Vec<f64> {
    let mut v: Vec<f64> = (1..=21).map(|k| 1000.0 * k as f64).collect();
    v.extend((0..=8).map(|k| 12_000.0 + 250.0 * k as f64));
    v.sort_by(f64::total_cmp);
    v.dedup();
    v
}

/// How the run settings depend on speed (step, settling and record length).
pub type SettingsAt<'a> = dyn Fn(f64) -> RunSettings + Sync + 'a;

/// One speed of the sweep.
#[derive(Debug, Clone)]
pub struct SweepPoint {
    /// Speed (rpm).
    pub speed_rpm: f64,
    /// Envelopes with the lubricated bearings.
    pub lubricated: Envelope,
    /// Envelopes with dry bearings.
    pub dry: Envelope,
    /// Steadiness measure of the two runs (see [`crate::analysis::simulate::STEADY_TOLERANCE`]).
    pub steadiness: [f64; 2],
    /// Wall time of the two runs (s) and simulated time per run (s).
    pub wall_seconds: f64,
    /// Simulated time per run (s).
    pub simulated_seconds: f64,
    /// Steps converged only to the bearing model's resolution (lubricated, dry).
    pub resolution_limited_steps: [usize; 2],
    /// Amplitude spectra (Hz, m) of the first bearing's inner-race y displacement over the
    /// record (lubricated, dry): the rows of the waterfall.
    pub spectra: [Vec<(f64, f64)>; 2],
    /// Lowest natural frequencies (Hz) with the bearings linearised at the static equilibrium
    /// of this speed (lubricated, dry): where the system resonances sit.
    pub natural_frequencies_hz: [Vec<f64>; 2],
    /// Friction of the roller bearings summed, at the static equilibrium of this speed
    /// (lubricated, dry; None without roller bearings): see [`friction_at_equilibrium`].
    pub friction: [Option<BearingFriction>; 2],
}

/// Spectrum of the first probe's (first bearing's) y displacement of a run.
pub fn inner_race_spectrum(r: &RunResult, sample_dt: f64) -> Vec<(f64, f64)> {
    let y: Vec<f64> = r.samples.iter().map(|s| s.probes[0][0][1]).collect();
    amplitude_spectrum(&y, sample_dt)
}

/// Lowest natural frequencies (Hz) of the rotor with the given bearings, linearised at the
/// static equilibrium at Ω (rad/s).
pub fn natural_frequencies_hz(
    model: &RotorModel,
    specs: &[BearingSpec],
    spin_speed: f64,
    count: usize,
) -> Result<Vec<f64>, OperatingError> {
    let mut m = model.clone();
    for (b, s) in m.description.bearings.iter_mut().zip(specs) {
        b.spec = s.clone();
    }
    let (_, modes) = operating_modes(&m, spin_speed, count, false)?;
    Ok(modes
        .iter()
        .map(|md| md.frequency / (2.0 * std::f64::consts::PI))
        .collect())
}

/// The friction torque, power loss and split of the rotor's roller bearings, summed, at the
/// static equilibrium at Ω (rad/s) with the given bearings; None when no bearing has a
/// friction model. Each bearing's own roller loads at that equilibrium; the dry bearing's
/// films from the regression formulas at its loads (see the roller bearing's `friction`).
pub fn friction_at_equilibrium(
    model: &RotorModel,
    specs: &[BearingSpec],
    spin_speed: f64,
) -> Result<Option<BearingFriction>, OperatingError> {
    let mut m = model.clone();
    for (b, s) in m.description.bearings.iter_mut().zip(specs) {
        b.spec = s.clone();
    }
    let mut bearings = build_bearings(&m)?;
    let eq = equilibrium(&m, spin_speed, &mut bearings)?;
    // Settles every bearing at the equilibrium, so its output is that state's.
    linearise(&m, &mut bearings, &eq.q, spin_speed)?;
    let mut total: Option<BearingFriction> = None;
    for b in &mut bearings {
        if let Some(f) = b.friction(spin_speed)? {
            let t = total.get_or_insert_with(BearingFriction::default);
            t.torque_nm += f.torque_nm;
            t.power_loss_w += f.power_loss_w;
            for (a, x) in t.power_loss_split_w.iter_mut().zip(f.power_loss_split_w) {
                *a += x;
            }
        }
    }
    Ok(total)
}

/// Runs the sweep. `lubricated_film` replaces the film of every roller bearing on the lubricated
/// side (None keeps each bearing's configured film); the dry side uses `FilmKind::Dry`.
/// `progress` is called once per finished run.
pub fn sweep(
    model: &RotorModel,
    speeds_rpm: &[f64],
    settings_at: &SettingsAt<'_>,
    lubricated_film: Option<FilmKind>,
    progress: &(dyn Fn() + Sync),
) -> Result<Vec<SweepPoint>, RunError> {
    let specs: Vec<BearingSpec> = model
        .description
        .bearings
        .iter()
        .map(|b| match lubricated_film {
            Some(film) => b.spec.with_film(film),
            None => b.spec.clone(),
        })
        .collect();
    let dry: Vec<BearingSpec> = specs.iter().map(|s| s.with_film(FilmKind::Dry)).collect();
    speeds_rpm
        .par_iter()
        .map(|&rpm| {
            let omega = rpm * std::f64::consts::PI / 30.0;
            let settings = settings_at(omega);
            let lub = run(model, &settings, Some(&specs))?;
            progress();
            let dr = run(model, &settings, Some(&dry))?;
            progress();
            let sample_dt = settings.dt * settings.record_every.max(1) as f64;
            let natural = |s: &[BearingSpec]| natural_frequencies_hz(model, s, omega, SWEEP_MODES);
            Ok(SweepPoint {
                speed_rpm: rpm,
                lubricated: lub.envelope,
                dry: dr.envelope,
                steadiness: [lub.steadiness, dr.steadiness],
                wall_seconds: lub.wall_seconds + dr.wall_seconds,
                simulated_seconds: settings.settle_time + settings.record_time,
                resolution_limited_steps: [
                    lub.resolution_limited_steps,
                    dr.resolution_limited_steps,
                ],
                spectra: [
                    inner_race_spectrum(&lub, sample_dt),
                    inner_race_spectrum(&dr, sample_dt),
                ],
                natural_frequencies_hz: [natural(&specs)?, natural(&dry)?],
                friction: [
                    friction_at_equilibrium(model, &specs, omega)?,
                    friction_at_equilibrium(model, &dry, omega)?,
                ],
            })
        })
        .collect()
}

/// Lubricated against dry at one speed of a sweep, and where the system resonance moved.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct FilmComparison {
    /// Speed compared (rpm).
    pub speed_rpm: f64,
    /// Largest central film over the loaded rollers, lubricated side (m).
    pub central_film_m: Option<f64>,
    /// Largest bearing stiffness envelope, lubricated and dry (N/m).
    pub bearing_stiffness_n_per_m: [f64; 2],
    /// (lubricated − dry) / dry of the bearing stiffness.
    pub stiffness_increase: f64,
    /// Lowest natural frequency at this speed, lubricated and dry (Hz).
    pub first_natural_frequency_hz: [f64; 2],
    /// Its shift, lubricated − dry (Hz).
    pub first_natural_frequency_shift_hz: f64,
    /// Lowest sweep speed at which the excitation order (e.g. gear mesh, teeth × speed)
    /// crosses the lowest natural frequency, lubricated and dry (rpm; None: no crossing within
    /// the sweep), interpolated linearly between sweep speeds.
    pub order_critical_speed_rpm: [Option<f64>; 2],
    /// Sweep speed of the largest inner-race displacement envelope, lubricated and dry (rpm).
    pub peak_response_speed_rpm: [f64; 2],
}

/// Compares the sides of a sweep at `speed_rpm` (the nearest sweep speed) with `order` the
/// excitation order whose crossing with the lowest natural frequency is sought (None: 1×).
pub fn compare_films(
    points: &[SweepPoint],
    speed_rpm: f64,
    order: Option<f64>,
) -> Option<FilmComparison> {
    let p = points.iter().min_by(|a, b| {
        (a.speed_rpm - speed_rpm)
            .abs()
            .total_cmp(&(b.speed_rpm - speed_rpm).abs())
    })?;
    let first = |p: &SweepPoint, side: usize| p.natural_frequencies_hz[side].first().copied();
    let f1 = [first(p, 0)?, first(p, 1)?];
    let order = order.unwrap_or(1.0);
    let crossing = |side: usize| {
        let mut sorted: Vec<&SweepPoint> = points.iter().collect();
        sorted.sort_by(|a, b| a.speed_rpm.total_cmp(&b.speed_rpm));
        let g = |p: &SweepPoint| first(p, side).map(|f| f - order * p.speed_rpm / 60.0);
        sorted.windows(2).find_map(|w| {
            let (a, b) = (g(w[0])?, g(w[1])?);
            (a >= 0.0 && b < 0.0)
                .then(|| w[0].speed_rpm + (w[1].speed_rpm - w[0].speed_rpm) * a / (a - b))
        })
    };
    let peak = |side: usize| {
        points
            .iter()
            .max_by(|a, b| {
                let e = |p: &SweepPoint| [p.lubricated, p.dry][side].max_displacement_m;
                e(a).total_cmp(&e(b))
            })
            .map_or(f64::NAN, |p| p.speed_rpm)
    };
    let k = [
        p.lubricated.max_bearing_stiffness_n_per_m,
        p.dry.max_bearing_stiffness_n_per_m,
    ];
    Some(FilmComparison {
        speed_rpm: p.speed_rpm,
        central_film_m: p.lubricated.max_central_film_m,
        bearing_stiffness_n_per_m: k,
        stiffness_increase: (k[0] - k[1]) / k[1],
        first_natural_frequency_hz: f1,
        first_natural_frequency_shift_hz: f1[0] - f1[1],
        order_critical_speed_rpm: [crossing(0), crossing(1)],
        peak_response_speed_rpm: [peak(0), peak(1)],
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(rpm: f64, k: [f64; 2], f1: [f64; 2], u: [f64; 2]) -> SweepPoint {
        let env = |k: f64, u: f64| Envelope {
            max_bearing_stiffness_n_per_m: k,
            max_displacement_m: u,
            max_central_film_m: Some(1e-6),
            ..Default::default()
        };
        SweepPoint {
            speed_rpm: rpm,
            lubricated: env(k[0], u[0]),
            dry: env(k[1], u[1]),
            steadiness: [0.0; 2],
            wall_seconds: 0.0,
            simulated_seconds: 0.0,
            resolution_limited_steps: [0; 2],
            spectra: [Vec::new(), Vec::new()],
            natural_frequencies_hz: [vec![f1[0]], vec![f1[1]]],
            friction: [None, None],
        }
    }

    /// Hand-computed: order 10 crosses f1 = 400 Hz (lubricated) at 2400 rpm and 300 Hz (dry)
    /// at 1800 rpm, between sweep speeds 1000 and 3000 rpm where the linear interpolation of
    /// f1 − 10 n/60 (400 − 166.67 = 233.33 → 400 − 500 = −100) gives 1000 + 2000 · 233.33/333.33.
    #[test]
    fn comparison_interpolates_the_order_crossing_and_reports_the_shift() {
        let points = [
            point(1000.0, [2e9, 1e9], [400.0, 300.0], [1e-6, 2e-6]),
            point(3000.0, [3e9, 1e9], [400.0, 300.0], [3e-6, 1e-6]),
        ];
        let c = compare_films(&points, 3000.0, Some(10.0)).unwrap();
        assert_eq!(c.speed_rpm, 3000.0);
        assert!((c.stiffness_increase - 2.0).abs() < 1e-12);
        assert!((c.first_natural_frequency_shift_hz - 100.0).abs() < 1e-12);
        let lub = c.order_critical_speed_rpm[0].unwrap();
        let dry = c.order_critical_speed_rpm[1].unwrap();
        assert!((lub - (1000.0 + 2000.0 * 233.333_333_333 / 333.333_333_333)).abs() < 1e-6);
        assert!((dry - (1000.0 + 2000.0 * 133.333_333_333 / 333.333_333_333)).abs() < 1e-6);
        assert_eq!(c.peak_response_speed_rpm, [3000.0, 1000.0]);
        assert_eq!(
            compare_films(&points, 3000.0, Some(1.0))
                .unwrap()
                .order_critical_speed_rpm,
            [None, None]
        );
    }
}
