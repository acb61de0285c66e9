//! Tangential forces of the lubricant film of one line contact: the sliding (viscous)
//! traction of an Eyring fluid, isothermal and thermal, and the rolling (inlet) resistance
//! (docs/physics.md §8.3).

use crate::math::{exp, ln, max, min, select, sqrt};

/// ln y above which asinh y = ln 2y to f32 precision; e^{ln y} is then not formed (it would
/// overflow f32 at the α·p of a hard EHL contact: up to ≈ 100).
const LN_LARGE_ARGUMENT: f32 = 20.0;

/// asinh y from ln y, without forming y where it would overflow (y > e^20: asinh y = ln 2y
/// there to f32 precision).
fn asinh_of_ln(ln_y: f32) -> f32 {
    let y = exp(min(ln_y, LN_LARGE_ARGUMENT));
    select(
        ln_y > LN_LARGE_ARGUMENT,
        core::f32::consts::LN_2 + ln_y,
        ln(y + sqrt(y * y + 1.0)),
    )
}

/// The isothermal Eyring traction of the contacts of one kind at one speed: what
/// [`IsothermalEyring::traction_n`] needs besides a contact's load and film.
///
/// At sliding speed u_s a film of thickness h(x) carries the Eyring shear stress
/// τ = τ₀·asinh(η(p)·u_s/(h·τ₀)) with the Barus viscosity η = η₀·e^{αp} (Johnson &
/// Tevaarwerk, Proc. R. Soc. A 356 (1977) 215–236). Over the pressure p_h·P(X) and film
/// h_c·H(X) of a line contact (X = x/b), which depend on Moes' M and L alone (and weakly on
/// p_h through the Dowson–Higginson density), the traction per length is b·τ₀·T with
///
/// T = ∫ asinh(N·e^{α·p_h·P(X)}/H(X)) dX,  N = η₀·u_s/(h_c·τ₀),
///
/// a function T(M, L, N) of the contact's shape, the mean stress ratio. The core reads it from
/// a table of the numerical solver's T ([`super::traction_table`], [`mean_stress_ratio`]):
/// the light, nearly rigid contacts, whose pressure is far lower and wider than Hertz's, are
/// then as right as the elastohydrodynamic ones (docs/physics.md §8.3).
#[derive(Clone, Copy, Debug)]
pub struct IsothermalEyring {
    eyring_stress_pa: f32,
    pressure_viscosity_pa_inv: f32,
    /// ln(E′·R) + ½·ln 2U (U = η₀·u/(E′·R)): ln M = ln w − this, w the load per length.
    ln_m_offset: f32,
    /// ln L = ln(α·E′) + ¼·ln 2U.
    ln_l: f32,
    /// ln(η₀·u_s/τ₀) (ln m): ln N = this − ln h_c.
    ln_newtonian_film: f32,
}

impl IsothermalEyring {
    /// For Eyring stress τ₀ (`eyring_stress_pa`), lubricant η₀ and α, entrainment speed u
    /// (`rolling_speed_m_s`, > 0), sliding speed u_s and the contact's reduced radius R and
    /// modulus E′.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        eyring_stress_pa: f32,
        viscosity_pa_s: f32,
        pressure_viscosity_pa_inv: f32,
        rolling_speed_m_s: f32,
        sliding_speed_m_s: f32,
        reduced_radius_m: f32,
        reduced_modulus_pa: f32,
    ) -> Self {
        let er = reduced_modulus_pa * reduced_radius_m;
        let ln_two_u = ln(2.0 * viscosity_pa_s * rolling_speed_m_s / er);
        Self {
            eyring_stress_pa,
            pressure_viscosity_pa_inv,
            ln_m_offset: ln(er) + 0.5 * ln_two_u,
            ln_l: ln(pressure_viscosity_pa_inv * reduced_modulus_pa) + 0.25 * ln_two_u,
            ln_newtonian_film: ln(viscosity_pa_s * sliding_speed_m_s / eyring_stress_pa),
        }
    }

    /// The traction (N) of a contact of length `length_m` l whose film carries `load_n` with
    /// Hertz half-width `half_width_m` b and peak pressure `peak_pressure_pa` p_h, at central
    /// film `film_m` h_c: l·b·τ₀·T(M, L, N). Two logarithms, an exponential and 64 table
    /// nodes, for every input.
    pub fn traction_n(
        &self,
        load_n: f32,
        length_m: f32,
        half_width_m: f32,
        peak_pressure_pa: f32,
        film_m: f32,
    ) -> f32 {
        let ln_m = ln(load_n / length_m) - self.ln_m_offset;
        let ln_newtonian = self.ln_newtonian_film - ln(film_m);
        let z = ln_newtonian + self.pressure_viscosity_pa_inv * peak_pressure_pa;
        length_m * half_width_m * self.eyring_stress_pa * mean_stress_ratio(ln_m, self.ln_l, z)
    }
}

/// Catmull–Rom weights of the four nodes k − 1 … k + 2 at t ∈ [0, 1] between k and k + 1.
fn catmull_rom(t: f32) -> [f32; 4] {
    let (t2, t3) = (t * t, t * t * t);
    [
        0.5 * (-t3 + 2.0 * t2 - t),
        0.5 * (3.0 * t3 - 5.0 * t2 + 2.0),
        0.5 * (-3.0 * t3 + 4.0 * t2 + t),
        0.5 * (t3 - t2),
    ]
}

/// The derivatives in t of [`catmull_rom`]'s weights: the slope per node step.
fn catmull_rom_slope(t: f32) -> [f32; 4] {
    let t2 = t * t;
    [
        0.5 * (-3.0 * t2 + 4.0 * t - 1.0),
        0.5 * (9.0 * t2 - 10.0 * t),
        0.5 * (-9.0 * t2 + 8.0 * t + 1.0),
        0.5 * (3.0 * t2 - 2.0 * t),
    ]
}

/// Cell k ∈ [1, nodes − 3] and position t ∈ [0, 1] in it of `x` on the axis of first node and
/// step `axis`, clamped to [node 1, node nodes − 2] (where the four nodes k − 1 … k + 2 exist);
/// NaN to node 1. Also the clamped coordinate.
fn cell(x: f32, axis: (f32, f32), nodes: usize) -> (usize, f32, f32) {
    let f = min(max((x - axis.0) / axis.1, 1.0), (nodes - 2) as f32);
    // f ∈ [1, nodes − 2]: the cast takes its integer part.
    let k = crate::math::min_index(f as usize, nodes - 3);
    (k, f - k as f32, axis.0 + f * axis.1)
}

/// How far above the table's last z [`mean_stress_ratio`] extrapolates.
const MAX_Z_ABOVE_TABLE: f32 = 1000.0;

/// The mean stress ratio T of [`IsothermalEyring`] at Moes' ln M, ln L and z = ln N + α·p_h:
/// Catmull–Rom tricubic in the table of ln T ([`super::traction_table`]), which covers the
/// film network's domain and its margin. Outside the interpolation's range of (ln M, ln L)
/// (node 1 to node n − 2 of each axis) T is read at the range's nearest point: a light roller
/// at high speed (ln M < −3.25) then reads low (docs/physics.md §8.3). Below the table's z
/// the film is Newtonian everywhere (T ∝ N: ln T continues with slope 1); above it T continues
/// linearly in z with the table's last slope (where asinh y = ln 2y the stress rises by τ₀ per
/// unit of ln N over the saturated zone).
pub fn mean_stress_ratio(ln_m: f32, ln_l: f32, z: f32) -> f32 {
    use super::traction_table::{
        LN_L, LN_M, LN_MEAN_STRESS_RATIO, LN_T_OFFSET, LN_T_STEP, L_NODES, M_NODES, Z, Z_NODES,
    };
    let (i, tm, _) = cell(ln_m, LN_M, M_NODES);
    let (j, tl, _) = cell(ln_l, LN_L, L_NODES);
    let (k, tz, zc) = cell(z, Z, Z_NODES);
    let (wm, wl, wz, dwz) = (
        catmull_rom(tm),
        catmull_rom(tl),
        catmull_rom(tz),
        catmull_rom_slope(tz),
    );
    // Σ over the 4 × 4 (M, L) nodes of their weight times their four z nodes.
    let mut along_z = [0.0_f32; 4];
    for (a, wa) in wm.iter().enumerate() {
        for (b, wb) in wl.iter().enumerate() {
            let w = wa * wb;
            let base = ((i + a - 1) * L_NODES + j + b - 1) * Z_NODES + k - 1;
            // In the table by construction (k + 2 < Z_NODES, i + 2 < M_NODES, j + 2 < L_NODES).
            let codes = LN_MEAN_STRESS_RATIO.get(base..base + 4).unwrap_or(&[0; 4]);
            for (acc, &code) in along_z.iter_mut().zip(codes) {
                *acc += w * f32::from(code);
            }
        }
    }
    let dot = |w: &[f32; 4]| {
        w[0] * along_z[0] + w[1] * along_z[1] + w[2] * along_z[2] + w[3] * along_z[3]
    };
    // The weights of each axis sum to 1, so the offset adds once.
    let ln_t = LN_T_OFFSET + LN_T_STEP * dot(&wz);
    let slope = LN_T_STEP * dot(&dwz) / Z.1;
    let below = min(z - zc, 0.0);
    // Capped where no contact reaches (N = e^1000 above the table) so that T stays finite.
    let above = min(max(z - zc, 0.0), MAX_Z_ABOVE_TABLE);
    exp(ln_t + below) * (1.0 + slope * above)
}

/// Coefficient c of the pressure-zone widening ([`pressure_zone_widening`]) of the thermal
/// traction's zone: the zone's rigid half-width is b_r with b_r² = c·R·h/(α·p_h), blended with
/// Hertz's b as b_eff = (b⁸ + b_r⁸)^{1/8} (b_eff = b to 10⁻³ where b_r < 0.4·b, b_r where
/// b_r > 2.5·b). c and the exponent 8 are fitted so that the isothermal Eyring traction over
/// the widened Hertz zone matches the one integrated over the numerical solver's pressure and
/// film (`bearing_ehl::traction`) for 240 contacts of the network's domain at slide-to-roll
/// ratios 0.3–10 %:
/// `cargo test --release -p bearing-tests --test friction_eyring -- --ignored fit_pressure_zone_widening --nocapture`
/// (docs/physics.md §8.3).
pub const WIDENING_COEFFICIENT: f32 = 5.0;

/// Floor on α·p_h in the widening: below it (the fit's contacts reach down to ≈ 1.9) the
/// contact is iso-viscous and its zone the rigid inlet's, b_r = √(c·R·h), which stays finite as
/// the load vanishes.
const MIN_ALPHA_PEAK_PRESSURE: f32 = 1.0;

/// b_eff/b ≥ 1: how much wider than Hertz's the pressure zone of a line contact is, from its
/// central film `film_m` h, reduced radius R, Hertz half-width b and α·p_h. An
/// elastohydrodynamic contact's pressure is Hertz's; a nearly rigid (light, fast, thick-film)
/// contact spreads its load over its hydrodynamic inlet, whose length scale is √(R·h)
/// (docs/physics.md §8.3), and its peak pressure is far below p_h. With the load kept,
/// p_eff·b_eff = p_h·b, the Barus viscosity e^{α·p_eff} then falls as the traction of the
/// numerical solution does. b_r² = c·R·h/(α·p_h) (`WIDENING_COEFFICIENT`): the rigid inlet
/// scale, narrowed where the pressure–viscosity effect (α·p_h ≥ 1) concentrates the pressure.
pub fn pressure_zone_widening(
    film_m: f32,
    reduced_radius_m: f32,
    half_width_m: f32,
    alpha_peak_pressure: f32,
) -> f32 {
    let ratio_sq = WIDENING_COEFFICIENT * reduced_radius_m * film_m
        / max(
            half_width_m * half_width_m * max(alpha_peak_pressure, MIN_ALPHA_PEAK_PRESSURE),
            f32::MIN_POSITIVE,
        );
    // (1 + r⁸)^{1/8} with r² = ratio_sq (capped so that r⁸ stays finite in f32).
    let r4 = {
        let r2 = min(ratio_sq, 1.0e9);
        r2 * r2
    };
    sqrt(sqrt(sqrt(1.0 + r4 * r4)))
}

/// What the thermal (Evans–Johnson) traction needs besides the contact.
#[derive(Clone, Copy, Debug)]
pub struct Thermal {
    /// τ₀ (Pa).
    pub eyring_stress_pa: f32,
    /// Fluid conductivity K (W/(m·K)).
    pub fluid_conductivity_w_mk: f32,
    /// Temperature–viscosity coefficient β_T (1/K).
    pub viscosity_temperature_k_inv: f32,
    /// K′·ρ′·c′ of the solids (W²·s/(m⁴·K²)).
    pub solid_effusivity_sq: f32,
}

/// Mean shear stress (Pa) of the thermal-Eyring regime of Evans & Johnson (Proc. IMechE C
/// 200 (1986) 313–324): τ̄ = 1.74·τ₀·[α·p̄/2 + ln((1.2/(τ₀·h))·√(2·K·η₀/(β_T·(1 + 9.6·ξ))))],
/// ξ = (4/π)·(K/(h/R))·√(p̄/(E′·R·K′ρ′c′·u)). The logarithm's argument needs a temperature
/// scale to be dimensionless: the temperature–viscosity coefficient β_T of the thermal
/// Eyring analysis (Johnson & Greenwood, Wear 61 (1980) 353–374) — docs/physics.md §8.3.
///
/// Evans & Johnson's bracket is ln A with A = e^{α·p̄/2}·(1.2/(τ₀·h))·√(…): the
/// large-argument form of an Eyring law, valid where A ≫ 1 (strongly non-Newtonian, thermal
/// plateau). Where light loads and thick films make A small the logarithm falls to zero and
/// below, a stress the fluid cannot have. The bracket is therefore taken as asinh(A/2), equal
/// to ln A to 1 % for A ≥ 4.5 (the paper's range) and tending to A/2 below: the
/// conduction-limited stress of a Newtonian film, 0.87·τ₀·A ∝ √(K·η₀/β_T)/h, which is
/// positive and falls with the film as the thermal Newtonian limit does. This regularisation
/// is this model's, not the paper's.
#[allow(clippy::too_many_arguments)]
pub fn evans_johnson_stress_pa(
    t: &Thermal,
    viscosity_pa_s: f32,
    pressure_viscosity_pa_inv: f32,
    mean_pressure_pa: f32,
    film_m: f32,
    reduced_radius_m: f32,
    reduced_modulus_pa: f32,
    rolling_speed_m_s: f32,
) -> f32 {
    let k = t.fluid_conductivity_w_mk;
    let xi = (4.0 / core::f32::consts::PI) * k * reduced_radius_m / film_m
        * sqrt(
            mean_pressure_pa
                / (reduced_modulus_pa
                    * reduced_radius_m
                    * t.solid_effusivity_sq
                    * rolling_speed_m_s),
        );
    let root = sqrt(2.0 * k * viscosity_pa_s / (t.viscosity_temperature_k_inv * (1.0 + 9.6 * xi)));
    let argument = 1.2 / (t.eyring_stress_pa * film_m) * root;
    let ln_half_a =
        0.5 * pressure_viscosity_pa_inv * mean_pressure_pa + ln(argument) - core::f32::consts::LN_2;
    1.74 * t.eyring_stress_pa * asinh_of_ln(ln_half_a)
}

/// The speed-dependent exponent and offset of the Goksem–Hargreaves rolling traction, from
/// the thermal loading L = η₀·β_T·u²/K: ln K_t = a(L)·ln D − c(L) (see [`rolling_n`]).
#[derive(Clone, Copy, Debug)]
pub struct RollingLaw {
    exponent: f32,
    offset: f32,
}

impl RollingLaw {
    /// For thermal loading `thermal_loading` L ≥ 0.
    pub fn new(thermal_loading: f32) -> Self {
        let l = max(thermal_loading, 0.0);
        Self {
            exponent: 0.658_228 + 0.010_638_3 * crate::math::pow(l, 0.317_460_3),
            offset: 0.162_625 + ln(1.0 + 0.411_483 * crate::math::pow(l, 0.707_071)),
        }
    }
}

/// Rolling (hydrodynamic inlet) resistance of a line contact (N), Goksem & Hargreaves (J.
/// Lubr. Technol. 100 (1978) 346–352), with its shear-heating factor: the dimensionless
/// rolling force per length f_R/(E′R) = W·K_t/G, with the load parameter W = Q/(l·E′·R),
/// G = α·E′, U = η₀·u/(E′·R), the dynamic loading parameter D = 11.812·G·U/W^{3/2} and
/// ln K_t = a(L)·ln D − c(L) ([`RollingLaw`]); isothermal (L = 0): K_t = 0.850·D^0.658, so
/// f_R ∝ W^0.013 hardly depends on the load. A floor of 10⁻⁹ 1/Pa on α (the fit is for
/// piezo-viscous oils; α → 0 would divide by 0) and of 1 mN on Q keep it finite.
#[allow(clippy::too_many_arguments)]
pub fn rolling_n(
    law: &RollingLaw,
    load_n: f32,
    length_m: f32,
    reduced_radius_m: f32,
    reduced_modulus_pa: f32,
    pressure_viscosity_pa_inv: f32,
    viscosity_pa_s: f32,
    rolling_speed_m_s: f32,
) -> f32 {
    let er = reduced_modulus_pa * reduced_radius_m;
    let w = max(load_n, 1.0e-3) / (length_m * er);
    let alpha = max(pressure_viscosity_pa_inv, 1.0e-9);
    let gu = alpha * viscosity_pa_s * rolling_speed_m_s / reduced_radius_m;
    let d = 11.812_207 * gu / (w * sqrt(w));
    let kt = exp(law.exponent * ln(d) - law.offset);
    length_m * reduced_radius_m * w * kt / alpha
}
