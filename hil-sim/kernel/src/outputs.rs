//! What one bearing step produces, and the little-endian record the firmware sends back.
//!
//! [`StepOutputs`] holds fixed-size arrays so that stepping never allocates, on the host and on
//! the Cortex-M4 alike. The firmware writes one record per step (the instruction count of the
//! step and of its friction call, then the outputs) into a semihosting file; the host decodes it
//! with the same code and compares it with its own replay of the trace:
//!
//! | part | layout |
//! |---|---|
//! | file header (16 bytes) | magic `BRGSTEPS`, version u16 = 2, rollers u16, count u32 |
//! | step record | instructions of the step u32 (TIM2), SysTick counts of the step u32, instructions of the friction call u32, F_x, F_y, θ_c, M_f, P, P_rolling, P_viscous, P_boundary (f32), then per roller Q, h_in, h_out, δ (f32) and the two film sources (u8) |
//! | trailer (28 bytes) | magic `BRGEND\0\0`, status u32 (0 = every step done), peak stack of the whole program u32, stack below the replay loop u32 (the step's own use), TIM2 and SysTick counts of a block of 1000 `nop` u32 ×2 (the calibration) |
//!
//! This file uses nothing from `std`: the firmware links this crate too.

pub use bearing_core::film::FilmSource;

/// Largest number of rollers a [`StepOutputs`] holds (the reference bearings have 12 and 17).
pub const MAX_ROLLERS: usize = 32;

/// The bearing-step outputs. Only the first `rollers` entries of each array are meaningful.
// `repr(C)`: the fields in this order keep every f32 the step writes within the 1020-byte
// offset reach of the M4's `vstr`, whatever fields are added at the end.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepOutputs {
    /// Force of the rollers on the inner race, (F_x, F_y) (N), docs/physics.md §4.
    pub force_n: [f32; 2],
    /// Cage angle θ_c (rad): roller j sits at θ_c + 2πj/Z (docs/physics.md §2). The accuracy
    /// reference needs it to put the rollers where the stepper had them.
    pub cage_angle_rad: f32,
    /// Number of rollers, Z.
    pub rollers: usize,
    /// Roller load Q_j (N), 0 for an unloaded roller.
    pub roller_load_n: [f32; MAX_ROLLERS],
    /// Central film at the inner-race contact, h_in,j (m).
    pub film_inner_m: [f32; MAX_ROLLERS],
    /// Central film at the outer-race contact, h_out,j (m).
    pub film_outer_m: [f32; MAX_ROLLERS],
    /// Geometric approach of roller j, x cos θ_j + y sin θ_j − g_r (m), before the films.
    pub roller_approach_m: [f32; MAX_ROLLERS],
    /// Which model served the inner contact.
    pub source_inner: [FilmSource; MAX_ROLLERS],
    /// Which model served the outer contact.
    pub source_outer: [FilmSource; MAX_ROLLERS],
    /// Friction torque on the inner ring (N·m; docs/physics.md §8.4), from the core's
    /// `Bearing::friction` after the step; 0 for the dry model.
    pub friction_torque_nm: f32,
    /// Power loss of the roller–race contacts (W), from the same call.
    pub power_loss_w: f32,
    /// The power loss split into [rolling, viscous, boundary] (W).
    pub power_loss_split_w: [f32; 3],
}

impl Default for StepOutputs {
    fn default() -> Self {
        Self {
            force_n: [0.0; 2],
            cage_angle_rad: 0.0,
            rollers: 0,
            roller_load_n: [0.0; MAX_ROLLERS],
            film_inner_m: [0.0; MAX_ROLLERS],
            film_outer_m: [0.0; MAX_ROLLERS],
            roller_approach_m: [0.0; MAX_ROLLERS],
            source_inner: [FilmSource::None; MAX_ROLLERS],
            source_outer: [FilmSource::None; MAX_ROLLERS],
            friction_torque_nm: 0.0,
            power_loss_w: 0.0,
            power_loss_split_w: [0.0; 3],
        }
    }
}

/// Magic of the firmware's output file.
pub const OUTPUT_MAGIC: [u8; 8] = *b"BRGSTEPS";
/// Magic of its trailer.
pub const TRAILER_MAGIC: [u8; 8] = *b"BRGEND\0\0";
/// Output format version.
pub const OUTPUT_VERSION: u16 = 2;
/// Output header size (bytes).
pub const OUTPUT_HEADER_LEN: usize = 16;
/// Trailer size (bytes).
pub const TRAILER_LEN: usize = 28;
/// Bytes of a step record before the per-roller part.
const RECORD_FIXED: usize = 44;
/// Bytes per roller in a step record.
const RECORD_PER_ROLLER: usize = 18;
/// Largest step record (bytes).
pub const OUTPUT_RECORD_MAX: usize = RECORD_FIXED + RECORD_PER_ROLLER * MAX_ROLLERS;

/// Size of one step record for `rollers` rollers (bytes).
pub const fn record_len(rollers: usize) -> usize {
    RECORD_FIXED + RECORD_PER_ROLLER * rollers
}

/// The output file header.
pub fn encode_output_header(rollers: u16, count: u32) -> [u8; OUTPUT_HEADER_LEN] {
    let mut out = [0u8; OUTPUT_HEADER_LEN];
    out[..8].copy_from_slice(&OUTPUT_MAGIC);
    out[8..10].copy_from_slice(&OUTPUT_VERSION.to_le_bytes());
    out[10..12].copy_from_slice(&rollers.to_le_bytes());
    out[12..16].copy_from_slice(&count.to_le_bytes());
    out
}

/// What the firmware reports after the last step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Trailer {
    /// 0 when every step was done, else the firmware's exit code.
    pub status: u32,
    /// Peak stack of the whole program since reset (bytes), by stack painting.
    pub stack_bytes: u32,
    /// Peak stack below the replay loop's frame (bytes): the step and the I/O calls.
    pub loop_stack_bytes: u32,
    /// TIM2 counts for a block of 1000 `nop`, minus the empty measurement (1000 expected).
    pub calibration_instructions: u32,
    /// SysTick counts for the same block (168–169 expected at 168 MHz).
    pub calibration_systick: u32,
}

impl Trailer {
    /// The trailer bytes.
    pub fn encode(&self) -> [u8; TRAILER_LEN] {
        let mut out = [0u8; TRAILER_LEN];
        out[..8].copy_from_slice(&TRAILER_MAGIC);
        out[8..12].copy_from_slice(&self.status.to_le_bytes());
        out[12..16].copy_from_slice(&self.stack_bytes.to_le_bytes());
        out[16..20].copy_from_slice(&self.loop_stack_bytes.to_le_bytes());
        out[20..24].copy_from_slice(&self.calibration_instructions.to_le_bytes());
        out[24..28].copy_from_slice(&self.calibration_systick.to_le_bytes());
        out
    }

    /// Decodes a trailer; `None` when the magic is wrong or the bytes too short.
    pub fn decode(bytes: &[u8]) -> Option<Trailer> {
        if bytes.get(..8)? != TRAILER_MAGIC {
            return None;
        }
        let word = |at: usize| -> Option<u32> {
            let mut w = [0u8; 4];
            w.copy_from_slice(bytes.get(at..at + 4)?);
            Some(u32::from_le_bytes(w))
        };
        Some(Trailer {
            status: word(8)?,
            stack_bytes: word(12)?,
            loop_stack_bytes: word(16)?,
            calibration_instructions: word(20)?,
            calibration_systick: word(24)?,
        })
    }
}

/// Writes one step record into `out`; returns its length. Rollers beyond [`MAX_ROLLERS`] are
/// not representable and are clamped.
pub fn encode_step(
    counts: &StepCounts,
    o: &StepOutputs,
    out: &mut [u8; OUTPUT_RECORD_MAX],
) -> usize {
    let rollers = if o.rollers > MAX_ROLLERS {
        MAX_ROLLERS
    } else {
        o.rollers
    };
    out[0..4].copy_from_slice(&counts.instructions.to_le_bytes());
    out[4..8].copy_from_slice(&counts.systick.to_le_bytes());
    out[8..12].copy_from_slice(&counts.friction_instructions.to_le_bytes());
    let mut at = 12;
    for value in [
        o.force_n[0],
        o.force_n[1],
        o.cage_angle_rad,
        o.friction_torque_nm,
        o.power_loss_w,
        o.power_loss_split_w[0],
        o.power_loss_split_w[1],
        o.power_loss_split_w[2],
    ] {
        out[at..at + 4].copy_from_slice(&value.to_le_bytes());
        at += 4;
    }
    for j in 0..rollers {
        for value in [
            o.roller_load_n[j],
            o.film_inner_m[j],
            o.film_outer_m[j],
            o.roller_approach_m[j],
        ] {
            out[at..at + 4].copy_from_slice(&value.to_le_bytes());
            at += 4;
        }
        out[at] = o.source_inner[j] as u8;
        out[at + 1] = o.source_outer[j] as u8;
        at += 2;
    }
    at
}

/// The film source of a byte, `None` for an unknown value.
pub fn film_source(byte: u8) -> Option<FilmSource> {
    Some(match byte {
        0 => FilmSource::None,
        1 => FilmSource::Regression,
        2 => FilmSource::NetworkF32,
        3 => FilmSource::NetworkInt,
        4 => FilmSource::Fallback,
        _ => return None,
    })
}

fn f32_at(bytes: &[u8], at: usize) -> Option<f32> {
    let mut word = [0u8; 4];
    word.copy_from_slice(bytes.get(at..at + 4)?);
    Some(f32::from_le_bytes(word))
}

/// The counters of one step.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct StepCounts {
    /// Instructions (TIM2 at 1 GHz of virtual time under `-icount shift=0`).
    pub instructions: u32,
    /// SysTick counts (168 MHz of virtual time).
    pub systick: u32,
    /// Instructions of the friction call after the step (`Bearing::friction`), timed apart.
    pub friction_instructions: u32,
}

/// Decodes one step record of `rollers` rollers. `None` when the bytes are too short, the
/// roller count too large or a film source unknown.
pub fn decode_step(bytes: &[u8], rollers: usize) -> Option<(StepCounts, StepOutputs)> {
    if rollers > MAX_ROLLERS || bytes.len() < record_len(rollers) {
        return None;
    }
    let word = |at: usize| -> Option<u32> {
        let mut w = [0u8; 4];
        w.copy_from_slice(bytes.get(at..at + 4)?);
        Some(u32::from_le_bytes(w))
    };
    let counts = StepCounts {
        instructions: word(0)?,
        systick: word(4)?,
        friction_instructions: word(8)?,
    };
    let mut o = StepOutputs {
        force_n: [f32_at(bytes, 12)?, f32_at(bytes, 16)?],
        cage_angle_rad: f32_at(bytes, 20)?,
        rollers,
        friction_torque_nm: f32_at(bytes, 24)?,
        power_loss_w: f32_at(bytes, 28)?,
        power_loss_split_w: [f32_at(bytes, 32)?, f32_at(bytes, 36)?, f32_at(bytes, 40)?],
        ..StepOutputs::default()
    };
    let mut at = RECORD_FIXED;
    for j in 0..rollers {
        o.roller_load_n[j] = f32_at(bytes, at)?;
        o.film_inner_m[j] = f32_at(bytes, at + 4)?;
        o.film_outer_m[j] = f32_at(bytes, at + 8)?;
        o.roller_approach_m[j] = f32_at(bytes, at + 12)?;
        o.source_inner[j] = film_source(*bytes.get(at + 16)?)?;
        o.source_outer[j] = film_source(*bytes.get(at + 17)?)?;
        at += RECORD_PER_ROLLER;
    }
    Some((counts, o))
}
