//! The C types of the interface: status codes, the choices passed as integers, the bearing
//! configuration by name, the per-step input and the output.
//!
//! Every type here is `#[repr(C)]` and holds only integers and floats, so any bit pattern a C
//! caller writes is a valid value: a choice (film model, contact law, preset) is a `uint32_t`
//! checked by the function that reads it, never a Rust enum that an out-of-range value would
//! make undefined.

use bearing_core::{ContactLaw, FilmKind, OutputView, RollerOutput};
use core::ffi::c_char;
use core::ptr::addr_of_mut;

/// What a function returns: `BEARING_STATUS_OK` or why it refused (docs/c-api.md, status codes).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BearingStatus {
    /// Done.
    Ok = 0,
    /// A pointer argument is NULL.
    NullPointer = 1,
    /// A pointer argument is not aligned for its type (the storage: `BEARING_STORAGE_ALIGN`).
    Misaligned = 2,
    /// The storage is smaller than `bearing_storage_size()`.
    StorageTooSmall = 3,
    /// The handle does not point at a bearing built by `bearing_init`.
    NotInitialised = 4,
    /// The configuration's roller count is valid but not one the library is built for (12, 17).
    UnsupportedRollerCount = 5,
    /// The film choice is not a `BearingFilm` value.
    UnknownFilm = 6,
    /// The contact law is not a `BearingContactLaw` value.
    UnknownContactLaw = 7,
    /// The preset is not a `BearingPreset` value.
    UnknownPreset = 8,
    /// A configuration field is out of its range; the refusal names it.
    InvalidConfig = 9,
    /// An operating-state field is out of its range or not finite; the refusal names it.
    InvalidState = 10,
    /// The time step is not finite or outside 0 … 1 s.
    InvalidTimeStep = 11,
    /// Another argument is out of its range (settle steps, cage angle, the shaft speed of
    /// `bearing_friction`); the refusal names it.
    InvalidArgument = 12,
}

/// The film model of a bearing (`BearingConfig::film`).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BearingFilm {
    /// The integer (quantised) neural network with its regression fallback.
    Int = 0,
    /// The f32 neural network with its regression fallback.
    F32 = 1,
    /// The regression formulas (Dowson–Toyoda / Dowson–Higginson blended with Martin's film).
    Regression = 2,
    /// No film: the dry slicing contact.
    Dry = 3,
}

/// The load–deflection law of the roller slices (`BearingConfig::contact_law`).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BearingContactLaw {
    /// Palmgren's slice law.
    Palmgren = 0,
    /// Lundberg's line-contact law.
    Lundberg = 1,
}

/// The bundled bearings (`bearing_preset`).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BearingPreset {
    /// The hub-motor shaft bearing of configs/hub_motor.toml: 17 rollers.
    HubMotor = 0,
    /// The test-rig bearing NU 205 ECP of configs/nu205.toml: 12 rollers.
    Nu205 = 1,
}

/// The film model of a `BearingFilm` value.
pub(crate) fn film_kind(value: u32) -> Option<FilmKind> {
    Some(match value {
        0 => FilmKind::Int,
        1 => FilmKind::F32,
        2 => FilmKind::Regression,
        3 => FilmKind::Dry,
        _ => return None,
    })
}

/// The `BearingFilm` value of a film model.
pub(crate) fn film_value(kind: FilmKind) -> u32 {
    match kind {
        FilmKind::Int => BearingFilm::Int as u32,
        FilmKind::F32 => BearingFilm::F32 as u32,
        FilmKind::Regression => BearingFilm::Regression as u32,
        FilmKind::Dry => BearingFilm::Dry as u32,
    }
}

/// The contact law of a `BearingContactLaw` value.
pub(crate) fn contact_law(value: u32) -> Option<ContactLaw> {
    Some(match value {
        0 => ContactLaw::Palmgren,
        1 => ContactLaw::Lundberg,
        _ => return None,
    })
}

/// The `BearingContactLaw` value of a contact law.
pub(crate) fn contact_law_value(law: ContactLaw) -> u32 {
    match law {
        ContactLaw::Palmgren => BearingContactLaw::Palmgren as u32,
        ContactLaw::Lundberg => BearingContactLaw::Lundberg as u32,
    }
}

/// Everything that defines a bearing, by name and unit: the fields of the core's
/// `BearingDesign` (the ranges are the core's, docs/c-api.md) and the film model.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BearingConfig {
    /// Pitch diameter d_m (m, 1 mm … 10 m).
    pub pitch_diameter_m: f32,
    /// Roller diameter D (m, below d_m).
    pub roller_diameter_m: f32,
    /// Effective contact length l (m, 0.1 mm … 1 m).
    pub roller_length_m: f32,
    /// Number of rollers Z (3 … 128 and Z·D < π·d_m; this library steps 12 or 17).
    pub roller_count: u32,
    /// Radial internal clearance g_r (m, −1 mm … 1 mm; negative: interference).
    pub radial_clearance_m: f32,
    /// Multiplier on the ISO/TS 16281 logarithmic crown (0 … 10; 0: straight roller).
    pub crown_scale: f32,
    /// Young's modulus of rings and rollers (Pa, 1 GPa … 1000 GPa).
    pub elastic_modulus_pa: f32,
    /// Poisson's ratio of rings and rollers (0 … 0.5).
    pub poisson_ratio: f32,
    /// Lubricant viscosity at ambient pressure η₀ (Pa·s, 10⁻⁵ … 10).
    pub viscosity_pa_s: f32,
    /// Pressure–viscosity coefficient α (1/Pa, 0 … 10⁻⁷).
    pub pressure_viscosity_pa_inv: f32,
    /// Lubricant density ρ₀ (kg/m³, 100 … 3000).
    pub density_kg_m3: f32,
    /// Load–deflection law of the slices: a `BearingContactLaw` value.
    pub contact_law: u32,
    /// Damping factor f_damp (s, 0 … 10⁻³).
    pub damping_factor_s: f32,
    /// Film model: a `BearingFilm` value.
    pub film: u32,
}

/// The inner-race motion of one step.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BearingState {
    /// Inner-race displacement [x, y] relative to the outer race (m, |·| ≤ 1 mm).
    pub displacement_m: [f32; 2],
    /// Inner-race velocity [ẋ, ẏ] (m/s, |·| ≤ 100).
    pub velocity_m_s: [f32; 2],
    /// Inner-race tilt [about x, about y] (rad, |·| ≤ 0.01).
    pub tilt_rad: [f32; 2],
    /// Shaft speed ω (rad/s, |ω| ≤ 10⁵; the sign gives the direction).
    pub shaft_speed_rad_s: f32,
}

/// Largest roller count of a bearing this library steps, the length of `BearingOutput::rollers`.
pub const BEARING_MAX_ROLLERS: usize = 17;

/// One roller after a step.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BearingRollerOutput {
    /// Roller angle θ_j from the x axis (rad, (−π, π]).
    pub angle_rad: f32,
    /// Geometric approach x·cos θ + y·sin θ − g_r, without film (m).
    pub geometric_approach_m: f32,
    /// Elastic approach of the roller middle, geometric approach + film (m).
    pub approach_m: f32,
    /// Central film at the inner contact (m).
    pub central_film_in_m: f32,
    /// Central film at the outer contact (m).
    pub central_film_out_m: f32,
    /// Minimum film at the inner contact (m).
    pub min_film_in_m: f32,
    /// Minimum film at the outer contact (m).
    pub min_film_out_m: f32,
    /// Contact load Q_j (N).
    pub load_n: f32,
    /// Viscous damping force (N).
    pub damping_force_n: f32,
    /// Roller moment (N·m).
    pub moment_nm: f32,
    /// Contact stiffness of the solids dQ_j/dδ_j (N/m).
    pub contact_stiffness_n_per_m: f32,
    /// Film-coupled roller stiffness dQ_j/d(geometric approach) (N/m).
    pub roller_stiffness_n_per_m: f32,
    /// Film ratio λ = h/σ of the inner contact (central film over the composite roughness,
    /// docs/physics.md §8.1), filled by `bearing_friction` (0 until then and for the dry model;
    /// a step leaves the last call's value).
    pub lambda_in: f32,
    /// Film ratio λ of the outer contact (as `lambda_in`).
    pub lambda_out: f32,
    /// Regime of the inner contact: 0 dry, 1 rigid iso-viscous, 2 elastic iso-viscous,
    /// 3 rigid piezo-viscous, 4 elastic piezo-viscous.
    pub regime_in: u8,
    /// Regime of the outer contact (as `regime_in`).
    pub regime_out: u8,
    /// Model that served the inner contact: 0 none, 1 regression, 2 f32 network,
    /// 3 integer network, 4 regression fallback of a network.
    pub film_source_in: u8,
    /// Model that served the outer contact (as `film_source_in`).
    pub film_source_out: u8,
}

/// The result of one step. Generalised coordinates of the inner race: (x, y, tilt about x,
/// tilt about y).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BearingOutput {
    /// Force of the rollers on the inner race [F_x, F_y] (N).
    pub force_n: [f32; 2],
    /// Moment of the rollers on the inner race [M_x, M_y] (N·m).
    pub moment_nm: [f32; 2],
    /// Stiffness −∂(F_x, F_y, M_x, M_y)/∂(x, y, tilt_x, tilt_y): N/m, N, N·m per rad.
    pub stiffness: [[f32; 4]; 4],
    /// Damping −∂(F_x, F_y)/∂(ẋ, ẏ) (N·s/m).
    pub damping_n_s_per_m: [[f32; 2]; 2],
    /// The cage angle θ_c after the step (rad): roller j sits at θ_c + 2πj/Z.
    pub cage_angle_rad: f32,
    /// Number of rollers Z: the first Z entries of `rollers` are meaningful, the rest zero.
    pub roller_count: u32,
    /// Each roller's centrifugal force on the outer race F_c (N; 0 when the bearing leaves it
    /// out, docs/physics.md §4.1).
    pub centrifugal_force_n: f32,
    /// Friction torque on the inner ring (N·m, docs/physics.md §8.4), filled by
    /// `bearing_friction` (0 until then and for the dry model; a step leaves the last call's
    /// value, so call `bearing_friction` after the step whose friction is wanted).
    pub friction_torque_nm: f32,
    /// Power loss of the roller–race contacts (W), filled by `bearing_friction`.
    pub power_loss_w: f32,
    /// The power loss split into [rolling, viscous, boundary] (W), filled by `bearing_friction`.
    pub power_loss_split_w: [f32; 3],
    /// Per-roller states.
    pub rollers: [BearingRollerOutput; BEARING_MAX_ROLLERS],
}

/// Capacity of the field names of a `BearingRefusal`, NUL included.
pub const BEARING_FIELD_NAME_LEN: usize = 48;

/// What a refused field allows (`BearingRefusal::allowed`).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BearingAllowed {
    /// Nothing was refused.
    Nothing = 0,
    /// A finite value above zero.
    Positive = 1,
    /// A finite value at or above zero.
    NonNegative = 2,
    /// A finite value of any sign.
    Finite = 3,
    /// A finite value in [`min`, `max`].
    Range = 4,
    /// A finite value below `max`, the value of the field `other_field`.
    LessThan = 5,
}

/// Why an argument was refused: the field, the value given and what is allowed, as data (the
/// library formats no text: a C program prints it as it likes, docs/c-api.md shows how).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BearingRefusal {
    /// Name of the refused field (`roller_diameter_m`, `displacement_x_m`, `time_step_s`, …),
    /// NUL-terminated; empty when nothing was refused.
    pub field: [c_char; BEARING_FIELD_NAME_LEN],
    /// The value that was given.
    pub value: f32,
    /// What is allowed: a `BearingAllowed` value.
    pub allowed: u32,
    /// Smallest allowed value (`BEARING_ALLOWED_RANGE`), else 0.
    pub min: f32,
    /// Largest allowed value (`BEARING_ALLOWED_RANGE`), the bound (`BEARING_ALLOWED_LESS_THAN`),
    /// else 0.
    pub max: f32,
    /// The field whose value is the bound (`BEARING_ALLOWED_LESS_THAN`), NUL-terminated, else
    /// empty.
    pub other_field: [c_char; BEARING_FIELD_NAME_LEN],
}

impl BearingRollerOutput {
    fn of(roller: &RollerOutput, [lambda_in, lambda_out]: [f32; 2]) -> Self {
        Self {
            angle_rad: roller.angle_rad,
            geometric_approach_m: roller.geometric_approach_m,
            approach_m: roller.approach_m,
            central_film_in_m: roller.central_film_in_m,
            central_film_out_m: roller.central_film_out_m,
            min_film_in_m: roller.min_film_in_m,
            min_film_out_m: roller.min_film_out_m,
            load_n: roller.load_n,
            damping_force_n: roller.damping_force_n,
            moment_nm: roller.moment_nm,
            contact_stiffness_n_per_m: roller.contact_stiffness_n_per_m,
            roller_stiffness_n_per_m: roller.roller_stiffness_n_per_m,
            lambda_in,
            lambda_out,
            regime_in: roller.regime_in as u8,
            regime_out: roller.regime_out as u8,
            film_source_in: roller.film_source_in as u8,
            film_source_out: roller.film_source_out as u8,
        }
    }

    const ZERO: Self = Self {
        angle_rad: 0.0,
        geometric_approach_m: 0.0,
        approach_m: 0.0,
        central_film_in_m: 0.0,
        central_film_out_m: 0.0,
        min_film_in_m: 0.0,
        min_film_out_m: 0.0,
        load_n: 0.0,
        damping_force_n: 0.0,
        moment_nm: 0.0,
        contact_stiffness_n_per_m: 0.0,
        roller_stiffness_n_per_m: 0.0,
        lambda_in: 0.0,
        lambda_out: 0.0,
        regime_in: 0,
        regime_out: 0,
        film_source_in: 0,
        film_source_out: 0,
    };
}

impl BearingOutput {
    /// Writes a core output and the cage angle after it to `*out`, field by field in place (a
    /// whole `BearingOutput` built first and then copied cost the M4 ≈ 1000 instructions more
    /// per step: zeroing and copying the whole struct, about a kilobyte).
    ///
    /// # Safety
    /// `out` is non-NULL, aligned and valid for writing a `BearingOutput`.
    pub(crate) unsafe fn write(view: &OutputView<'_>, cage_angle_rad: f32, out: *mut Self) {
        // SAFETY: the caller's contract; each field is written through a raw pointer, so no
        // reference to possibly uninitialised memory is made.
        let totals = &view.totals;
        unsafe {
            addr_of_mut!((*out).force_n).write(totals.force_n);
            addr_of_mut!((*out).moment_nm).write(totals.moment_nm);
            addr_of_mut!((*out).stiffness).write(totals.stiffness);
            addr_of_mut!((*out).damping_n_s_per_m).write(totals.damping_n_s_per_m);
            addr_of_mut!((*out).cage_angle_rad).write(cage_angle_rad);
            addr_of_mut!((*out).centrifugal_force_n).write(totals.centrifugal_force_n);
            addr_of_mut!((*out).friction_torque_nm).write(totals.friction_torque_nm);
            addr_of_mut!((*out).power_loss_w).write(totals.power_loss_w);
            addr_of_mut!((*out).power_loss_split_w).write(totals.power_loss_split_w);
            // At most BEARING_MAX_ROLLERS (17): the storage holds no larger bearing.
            let count = view.rollers.len().min(BEARING_MAX_ROLLERS);
            addr_of_mut!((*out).roller_count).write(count as u32);
            let rollers = addr_of_mut!((*out).rollers).cast::<BearingRollerOutput>();
            for j in 0..BEARING_MAX_ROLLERS {
                let lambda = view.lambda.get(j).copied().unwrap_or([0.0; 2]);
                let roller = view.rollers.get(j).map_or(BearingRollerOutput::ZERO, |r| {
                    BearingRollerOutput::of(r, lambda)
                });
                // j < BEARING_MAX_ROLLERS: inside the array.
                rollers.add(j).write(roller);
            }
        }
    }
}
