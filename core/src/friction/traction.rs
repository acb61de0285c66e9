//! Tangential forces of the lubricant film of one line contact: the sliding (viscous)
//! traction of an Eyring fluid, isothermal and thermal, and the rolling (inlet) resistance
//! (docs/physics.md §8.3).

use crate::math::{exp, ln, max, min, select, sqrt};

/// Nodes cos θ_i and weights w_i·cos θ_i of the 4-point Gauss–Legendre rule on θ ∈ [0, π/2]
/// for ∫₀^{π/2} g(p_max·cos θ)·cos θ dθ = ∫₀¹ g(p_max·√(1 − ξ²)) dξ, the mean of g over a
/// Hertzian half-width (ξ = sin θ removes the square-root end of the Hertz profile). Against
/// a 200 001-point trapezoid rule on g = asinh(A·e^{a cos θ}), A ∈ [10⁻⁷, 1], a ∈ [4, 30],
/// its largest error is 3.6 % (3 nodes: 9.7 %, 5 nodes: 2.1 %).
const NODES: [(f32, f32); 4] = gauss_nodes();

const fn gauss_nodes() -> [(f32, f32); 4] {
    // Gauss–Legendre on [−1, 1]: ±0.339 981 04 (weight 0.652 145 15), ±0.861 136 31
    // (0.347 854 85); θ = (π/4)(1 + x), weight (π/4)·w. cos θ is tabulated (const fn has no
    // cosine); the values below are cos((π/4)(1 + x)).
    let q = core::f32::consts::FRAC_PI_4;
    [
        (0.994_058_5, q * 0.347_854_85 * 0.994_058_5),
        (0.868_624_1, q * 0.652_145_15 * 0.868_624_1),
        (0.495_471_6, q * 0.652_145_15 * 0.495_471_6),
        (0.108_847_2, q * 0.347_854_85 * 0.108_847_2),
    ]
}

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

/// Isothermal Eyring traction (N) of a film of thickness `film_m` carrying the Hertzian
/// pressure of peak `peak_pressure_pa` over half-width b (`half_width_m`) and length l: the
/// shear stress τ = τ₀·asinh(η(p)·u_s/(h·τ₀)) with the Barus viscosity η = η₀·e^{αp}
/// (Johnson & Tevaarwerk, Proc. R. Soc. A 356 (1977) 215–236), integrated over the contact
/// by a 4-node Gauss–Legendre rule (`NODES`).
#[allow(clippy::too_many_arguments)]
pub fn isothermal_eyring_n(
    eyring_stress_pa: f32,
    viscosity_pa_s: f32,
    pressure_viscosity_pa_inv: f32,
    sliding_speed_m_s: f32,
    film_m: f32,
    peak_pressure_pa: f32,
    half_width_m: f32,
    length_m: f32,
) -> f32 {
    let ln_newtonian = ln(viscosity_pa_s * sliding_speed_m_s / (film_m * eyring_stress_pa));
    let a = pressure_viscosity_pa_inv * peak_pressure_pa;
    let mean: f32 = NODES
        .iter()
        .map(|&(c, w)| w * asinh_of_ln(ln_newtonian + a * c))
        .sum();
    // ∫ over −b … b is twice the half-width mean.
    2.0 * half_width_m * length_m * eyring_stress_pa * mean
}

/// Coefficient c of the pressure-zone widening ([`pressure_zone_widening`]): the zone's
/// rigid half-width is b_r with b_r² = c·R·h/(α·p_h), blended with Hertz's b as
/// b_eff = (b⁸ + b_r⁸)^{1/8} (b_eff = b to 10⁻³ where b_r < 0.4·b, b_r where b_r > 2.5·b).
/// c and the exponent 8 are fitted to the isothermal Eyring traction integrated over the
/// numerical solver's pressure and film (`bearing_ehl::traction`) for 240 contacts of the
/// network's domain at slide-to-roll ratios 0.3–10 %, none of them among the contacts the
/// accuracy test reports:
/// `cargo test --release -p bearing-tests --test friction_eyring -- --ignored --nocapture`
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
