//! The FMU's variables: one table that modelDescription.xml is written from and that the shared
//! library reads and writes by value reference, so the two cannot disagree.
//!
//! Real value references: inputs 0–6, outputs 7–40, parameters 41–51 (the order of
//! [`REALS`]). Integer value references: [`INTEGERS`]. The generalised coordinates of the inner
//! race are (x, y, tilt about x, tilt about y), as in the core's output
//! (`bearing_core::BearingOutput`).

use bearing_core::film::FilmSource;
use bearing_core::{BearingDesign, ContactLaw, FilmKind, OperatingState, OutputView};

/// Causality of a variable (FMI 2.0 §2.2.7).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Causality {
    /// Set by the importer at every communication point.
    Input,
    /// Computed by the FMU.
    Output,
    /// Set before initialisation (fixed) or also between steps (tunable).
    Parameter,
}

/// Variability of a parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Variability {
    /// Inputs and outputs: may change at every communication point.
    Continuous,
    /// A parameter set before initialisation only.
    Fixed,
    /// A parameter that may also change between steps.
    Tunable,
}

/// One Real variable.
#[derive(Clone, Copy, Debug)]
pub struct RealVariable {
    /// Name in modelDescription.xml.
    pub name: &'static str,
    /// Causality.
    pub causality: Causality,
    /// Variability.
    pub variability: Variability,
    /// Unit name, one of [`UNITS`].
    pub unit: &'static str,
    /// Description in modelDescription.xml.
    pub description: &'static str,
}

const fn input(name: &'static str, unit: &'static str, description: &'static str) -> RealVariable {
    RealVariable {
        name,
        causality: Causality::Input,
        variability: Variability::Continuous,
        unit,
        description,
    }
}

const fn output(name: &'static str, unit: &'static str, description: &'static str) -> RealVariable {
    RealVariable {
        name,
        causality: Causality::Output,
        variability: Variability::Continuous,
        unit,
        description,
    }
}

const fn parameter(
    name: &'static str,
    variability: Variability,
    unit: &'static str,
    description: &'static str,
) -> RealVariable {
    RealVariable {
        name,
        causality: Causality::Parameter,
        variability,
        unit,
        description,
    }
}

/// Number of Real inputs.
pub const INPUTS: usize = 7;
/// Number of Real outputs.
pub const OUTPUTS: usize = 34;
/// Number of Real parameters.
pub const PARAMETERS: usize = 11;
/// Value reference of the first output.
pub const FIRST_OUTPUT: usize = INPUTS;
/// Value reference of the first parameter.
pub const FIRST_PARAMETER: usize = INPUTS + OUTPUTS;

use Variability::{Fixed, Tunable};

/// Every Real variable; its index is its value reference.
pub const REALS: [RealVariable; INPUTS + OUTPUTS + PARAMETERS] = [
    input(
        "displacement_x_m",
        "m",
        "Inner-race displacement x in the bearing plane",
    ),
    input(
        "displacement_y_m",
        "m",
        "Inner-race displacement y in the bearing plane",
    ),
    input("velocity_x_m_s", "m/s", "Inner-race velocity dx/dt"),
    input("velocity_y_m_s", "m/s", "Inner-race velocity dy/dt"),
    input("tilt_x_rad", "rad", "Inner-race tilt about the x axis"),
    input("tilt_y_rad", "rad", "Inner-race tilt about the y axis"),
    input(
        "shaft_speed_rad_s",
        "rad/s",
        "Shaft (inner-race) speed; the outer race is fixed",
    ),
    output(
        "force_x_n",
        "N",
        "Force of the rollers on the inner race, x",
    ),
    output(
        "force_y_n",
        "N",
        "Force of the rollers on the inner race, y",
    ),
    output(
        "moment_x_nm",
        "N.m",
        "Moment of the rollers on the inner race about x",
    ),
    output(
        "moment_y_nm",
        "N.m",
        "Moment of the rollers on the inner race about y",
    ),
    output("stiffness_x_x", "N/m", "Stiffness -dFx/dx"),
    output("stiffness_x_y", "N/m", "Stiffness -dFx/dy"),
    output("stiffness_x_tilt_x", "N/rad", "Stiffness -dFx/d(tilt_x)"),
    output("stiffness_x_tilt_y", "N/rad", "Stiffness -dFx/d(tilt_y)"),
    output("stiffness_y_x", "N/m", "Stiffness -dFy/dx"),
    output("stiffness_y_y", "N/m", "Stiffness -dFy/dy"),
    output("stiffness_y_tilt_x", "N/rad", "Stiffness -dFy/d(tilt_x)"),
    output("stiffness_y_tilt_y", "N/rad", "Stiffness -dFy/d(tilt_y)"),
    output("stiffness_tilt_x_x", "N", "Stiffness -dMx/dx (N.m per m)"),
    output("stiffness_tilt_x_y", "N", "Stiffness -dMx/dy (N.m per m)"),
    output(
        "stiffness_tilt_x_tilt_x",
        "N.m/rad",
        "Stiffness -dMx/d(tilt_x)",
    ),
    output(
        "stiffness_tilt_x_tilt_y",
        "N.m/rad",
        "Stiffness -dMx/d(tilt_y)",
    ),
    output("stiffness_tilt_y_x", "N", "Stiffness -dMy/dx (N.m per m)"),
    output("stiffness_tilt_y_y", "N", "Stiffness -dMy/dy (N.m per m)"),
    output(
        "stiffness_tilt_y_tilt_x",
        "N.m/rad",
        "Stiffness -dMy/d(tilt_x)",
    ),
    output(
        "stiffness_tilt_y_tilt_y",
        "N.m/rad",
        "Stiffness -dMy/d(tilt_y)",
    ),
    output("damping_x_x", "N.s/m", "Damping -dFx/d(dx/dt)"),
    output("damping_x_y", "N.s/m", "Damping -dFx/d(dy/dt)"),
    output("damping_y_x", "N.s/m", "Damping -dFy/d(dx/dt)"),
    output("damping_y_y", "N.s/m", "Damping -dFy/d(dy/dt)"),
    output("max_roller_load_n", "N", "Largest roller load"),
    output(
        "min_film_m",
        "m",
        "Smallest minimum film over every inner and outer contact (0 at standstill and dry)",
    ),
    output(
        "max_film_m",
        "m",
        "Largest central film over every inner and outer contact (0 at standstill and dry)",
    ),
    output(
        "network_fraction",
        "1",
        "Fraction of the contacts whose film a neural network served (the rest: regression \
         formulas, fallback or no film)",
    ),
    output(
        "cage_angle_rad",
        "rad",
        "Cage angle; roller j sits at it + 2 pi j / Z",
    ),
    output(
        "friction_torque_nm",
        "N.m",
        "Friction torque on the inner ring of the roller-race contacts (mixed EHL: rolling, \
         viscous and boundary parts), computed after each step (0 for the dry model)",
    ),
    output(
        "power_loss_w",
        "W",
        "Power loss of the roller-race contacts, friction torque times shaft speed",
    ),
    output(
        "power_loss_rolling_w",
        "W",
        "Part of the power loss from the rolling (hydrodynamic inlet) resistance of the films",
    ),
    output(
        "power_loss_viscous_w",
        "W",
        "Part of the power loss from the viscous (Eyring) shear of the films",
    ),
    output(
        "power_loss_boundary_w",
        "W",
        "Part of the power loss from the boundary friction of the asperities",
    ),
    parameter("pitch_diameter_m", Fixed, "m", "Pitch diameter d_m"),
    parameter("roller_diameter_m", Fixed, "m", "Roller diameter D"),
    parameter(
        "roller_length_m",
        Fixed,
        "m",
        "Effective roller contact length l",
    ),
    parameter(
        "radial_clearance_m",
        Fixed,
        "m",
        "Radial clearance per roller (negative: interference)",
    ),
    parameter(
        "crown_scale",
        Fixed,
        "1",
        "Multiplier on the ISO/TS 16281 logarithmic crown (0: straight roller)",
    ),
    parameter(
        "elastic_modulus_pa",
        Fixed,
        "Pa",
        "Elastic modulus of rings and rollers",
    ),
    parameter(
        "poisson_ratio",
        Fixed,
        "1",
        "Poisson ratio of rings and rollers",
    ),
    parameter(
        "viscosity_pa_s",
        Tunable,
        "Pa.s",
        "Lubricant viscosity at ambient pressure (tunable: follows the oil temperature)",
    ),
    parameter(
        "pressure_viscosity_pa_inv",
        Tunable,
        "1/Pa",
        "Lubricant pressure-viscosity coefficient alpha (tunable: follows the oil temperature)",
    ),
    parameter(
        "density_kg_m3",
        Tunable,
        "kg/m3",
        "Lubricant density at ambient pressure (tunable)",
    ),
    parameter(
        "damping_factor_s",
        Tunable,
        "s",
        "Damping factor f_damp: each roller's viscous force is f_damp times its contact stiffness \
         times its approach speed (tunable)",
    ),
];

/// One Integer parameter (fixed: each chooses compiled code).
#[derive(Clone, Copy, Debug)]
pub struct IntegerVariable {
    /// Name in modelDescription.xml.
    pub name: &'static str,
    /// Smallest allowed value.
    pub min: i32,
    /// Largest allowed value.
    pub max: i32,
    /// Description in modelDescription.xml.
    pub description: &'static str,
}

/// Every Integer variable; its index is its value reference.
pub const INTEGERS: [IntegerVariable; 3] = [
    IntegerVariable {
        name: "roller_count",
        min: bearing_core::bearing::MIN_ROLLERS as i32,
        max: bearing_core::bearing::MAX_ROLLERS as i32,
        description: "Number of rollers Z",
    },
    IntegerVariable {
        name: "contact_law",
        min: 0,
        max: 1,
        description: "Slice contact law: 0 Palmgren, 1 Lundberg",
    },
    IntegerVariable {
        name: "film_model",
        min: 0,
        max: 3,
        description: "Film model: 0 integer network, 1 f32 network, 2 regression formulas, 3 dry \
                      (no film)",
    },
];

/// Units: name and SI base-unit exponents (kg, m, s, rad) of each unit [`REALS`] uses.
pub const UNITS: [(&str, [i8; 4]); 17] = [
    ("m", [0, 1, 0, 0]),
    ("m/s", [0, 1, -1, 0]),
    ("rad", [0, 0, 0, 1]),
    ("rad/s", [0, 0, -1, 1]),
    ("N", [1, 1, -2, 0]),
    ("N.m", [1, 2, -2, 0]),
    ("N/m", [1, 0, -2, 0]),
    ("N/rad", [1, 1, -2, -1]),
    ("N.m/rad", [1, 2, -2, -1]),
    ("N.s/m", [1, 0, -1, 0]),
    ("1", [0, 0, 0, 0]),
    ("Pa", [1, -1, -2, 0]),
    ("Pa.s", [1, -1, -1, 0]),
    ("1/Pa", [-1, 1, 2, 0]),
    ("kg/m3", [1, -3, 0, 0]),
    ("s", [0, 0, 1, 0]),
    ("W", [1, 2, -3, 0]),
];

/// The film model's code in the `film_model` Integer parameter.
pub fn film_code(film: FilmKind) -> i32 {
    match film {
        FilmKind::Int => 0,
        FilmKind::F32 => 1,
        FilmKind::Regression => 2,
        FilmKind::Dry => 3,
    }
}

/// The film model of a `film_model` code.
pub fn film_of_code(code: i32) -> Option<FilmKind> {
    FilmKind::ALL.into_iter().find(|&k| film_code(k) == code)
}

/// The contact law's code in the `contact_law` Integer parameter.
pub fn law_code(law: ContactLaw) -> i32 {
    match law {
        ContactLaw::Palmgren => 0,
        ContactLaw::Lundberg => 1,
    }
}

/// Real parameter values (in [`REALS`] order from [`FIRST_PARAMETER`]) and Integer values (in
/// [`INTEGERS`] order) of a design and film model.
pub fn parameter_values(
    design: &BearingDesign,
    film: FilmKind,
) -> ([f64; PARAMETERS], [i32; INTEGERS.len()]) {
    let d = design;
    let reals = [
        d.pitch_diameter_m,
        d.roller_diameter_m,
        d.roller_length_m,
        d.radial_clearance_m,
        d.crown_scale,
        d.elastic_modulus_pa,
        d.poisson_ratio,
        d.viscosity_pa_s,
        d.pressure_viscosity_pa_inv,
        d.density_kg_m3,
        d.damping_factor_s,
    ]
    .map(f64::from);
    let integers = [
        i32::from(d.roller_count),
        law_code(d.contact_law),
        film_code(film),
    ];
    (reals, integers)
}

/// The design of parameter values: the inverse of [`parameter_values`] (f64 rounded to f32,
/// the core's type). Integers out of range are refused by name.
pub fn design_of(
    reals: &[f64; PARAMETERS],
    integers: &[i32; INTEGERS.len()],
) -> Result<(BearingDesign, FilmKind), String> {
    for (v, value) in INTEGERS.iter().zip(integers) {
        if !(v.min..=v.max).contains(value) {
            return Err(format!(
                "{} = {value} is not allowed: it must lie in [{}, {}]",
                v.name, v.min, v.max
            ));
        }
    }
    let [roller_count, law, film] = *integers;
    let r = reals.map(|v| v as f32);
    let design = BearingDesign {
        pitch_diameter_m: r[0],
        roller_diameter_m: r[1],
        roller_length_m: r[2],
        roller_count: u16::try_from(roller_count).unwrap_or(0),
        radial_clearance_m: r[3],
        crown_scale: r[4],
        elastic_modulus_pa: r[5],
        poisson_ratio: r[6],
        viscosity_pa_s: r[7],
        pressure_viscosity_pa_inv: r[8],
        density_kg_m3: r[9],
        contact_law: if law == 1 {
            ContactLaw::Lundberg
        } else {
            ContactLaw::Palmgren
        },
        damping_factor_s: r[10],
    };
    let film = film_of_code(film).unwrap_or(FilmKind::Int);
    Ok((design, film))
}

/// The operating state of the Real inputs (f64 rounded to the core's f32), unchecked: the
/// core's step checks it and names a refused field.
pub fn operating_state(inputs: &[f64; INPUTS]) -> OperatingState {
    let v = inputs.map(|v| v as f32);
    OperatingState {
        displacement_m: [v[0], v[1]],
        velocity_m_s: [v[2], v[3]],
        tilt_rad: [v[4], v[5]],
        shaft_speed_rad_s: v[6],
    }
}

/// The outputs of a step (f32 widened exactly to f64), in [`REALS`] order from
/// [`FIRST_OUTPUT`]; `cage_angle_rad` is the bearing's after the step, and the friction
/// fields are those of the bearing's last `friction` call (the FMU makes it after every step).
pub fn output_values(out: &OutputView<'_>, cage_angle_rad: f32) -> [f64; OUTPUTS] {
    let mut values = [0.0_f32; OUTPUTS];
    let mut k = 0;
    let mut push = |v: f32| {
        if let Some(slot) = values.get_mut(k) {
            *slot = v;
        }
        k += 1;
    };
    out.force_n.into_iter().for_each(&mut push);
    out.moment_nm.into_iter().for_each(&mut push);
    out.stiffness.into_iter().flatten().for_each(&mut push);
    out.damping_n_s_per_m
        .into_iter()
        .flatten()
        .for_each(&mut push);
    push(out.max_roller_load_n());
    let films = |r: &bearing_core::RollerOutput| {
        (
            r.min_film_in_m.min(r.min_film_out_m),
            r.central_film_in_m.max(r.central_film_out_m),
        )
    };
    let (min_film, max_film) = out
        .rollers
        .iter()
        .map(films)
        .fold((f32::INFINITY, 0.0_f32), |(lo, hi), (min, max)| {
            (lo.min(min), hi.max(max))
        });
    push(if out.rollers.is_empty() {
        0.0
    } else {
        min_film
    });
    push(max_film);
    let contacts = 2 * out.rollers.len();
    let network = out.contacts_served_by(FilmSource::NetworkInt)
        + out.contacts_served_by(FilmSource::NetworkF32);
    push(if contacts == 0 {
        0.0
    } else {
        network as f32 / contacts as f32
    });
    push(cage_angle_rad);
    push(out.friction_torque_nm);
    push(out.power_loss_w);
    out.power_loss_split_w.into_iter().for_each(&mut push);
    values.map(f64::from)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_sizes_and_units_agree() {
        let causalities = |c| REALS.iter().filter(|v| v.causality == c).count();
        assert_eq!(causalities(Causality::Input), INPUTS);
        assert_eq!(causalities(Causality::Output), OUTPUTS);
        assert_eq!(causalities(Causality::Parameter), PARAMETERS);
        assert!(REALS[..INPUTS]
            .iter()
            .all(|v| v.causality == Causality::Input));
        assert!(REALS[FIRST_PARAMETER..]
            .iter()
            .all(|v| v.causality == Causality::Parameter));
        for v in REALS {
            assert!(
                UNITS.iter().any(|(u, _)| *u == v.unit),
                "{}: unit {} not defined",
                v.name,
                v.unit
            );
        }
    }

    #[test]
    fn parameters_round_trip_through_the_design() {
        for film in FilmKind::ALL {
            let (reals, integers) = parameter_values(&BearingDesign::NU205, film);
            let (design, back) = design_of(&reals, &integers).unwrap();
            assert_eq!(back, film);
            assert_eq!(design, BearingDesign::NU205);
        }
        let (reals, mut integers) = parameter_values(&BearingDesign::NU205, FilmKind::Int);
        integers[2] = 4;
        let refused = design_of(&reals, &integers).unwrap_err();
        assert!(refused.contains("film_model = 4"), "{refused}");
    }
}
