//! Lubrication regime of a contact from the Moes asymptotes (docs/physics.md §4, §5.1).
//!
//! Moes' formula combines four asymptotic solutions: rigid/elastic × iso-/piezo-viscous,
//! H_RI = 3/M, H_EI = 2.621·M^−1/5, H_RP = 1.287·L^2/3, H_EP = 1.311·M^−1/8·L^3/4. The
//! iso-viscous pair combines like a maximum, the piezo-viscous pair like a minimum, and the two
//! groups again like a maximum; the regime is the asymptote that dominates (the boundaries of
//! the Greenwood / Johnson chart). Computed from ln M and ln L, so it costs a few additions.

/// Which Moes asymptote dominates a contact.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[repr(u8)]
pub enum Regime {
    /// No entrainment or no load: no film regime (dry contact).
    #[default]
    Dry = 0,
    /// Rigid, iso-viscous (hydrodynamic, Martin).
    RigidIsoviscous = 1,
    /// Elastic, iso-viscous (soft EHL).
    ElasticIsoviscous = 2,
    /// Rigid, piezo-viscous.
    RigidPiezoviscous = 3,
    /// Elastic, piezo-viscous: hard EHL, where the network is trained.
    ElasticPiezoviscous = 4,
}

impl Regime {
    /// Short name for reports and JSON.
    pub fn name(self) -> &'static str {
        match self {
            Regime::Dry => "dry",
            Regime::RigidIsoviscous => "rigid_isoviscous",
            Regime::ElasticIsoviscous => "elastic_isoviscous",
            Regime::RigidPiezoviscous => "rigid_piezoviscous",
            Regime::ElasticPiezoviscous => "elastic_piezoviscous",
        }
    }

    /// Regime for Moes parameters given as ln M and ln L.
    pub fn from_ln_moes(ln_m: f32, ln_l: f32) -> Regime {
        // ln of the four asymptotes.
        let ri = LN_RI - ln_m;
        let ei = LN_EI - 0.2 * ln_m;
        let rp = LN_RP + (2.0 / 3.0) * ln_l;
        let ep = LN_EP - 0.125 * ln_m + 0.75 * ln_l;
        let iso = crate::math::max(ri, ei);
        let piezo = crate::math::min(rp, ep);
        // Branch-free (the step's work must not depend on the data): an index into a table.
        let piezoviscous = usize::from(piezo >= iso);
        let elastic_piezo = usize::from(ep <= rp);
        let rigid_iso = usize::from(ri >= ei);
        let finite = ln_m.is_finite() & ln_l.is_finite();
        Self::from_flags(
            finite,
            piezoviscous == 1,
            elastic_piezo == 1,
            rigid_iso == 1,
        )
    }

    /// The regime from the chart's three comparisons, branch-free: an index into a table.
    #[inline(always)]
    fn from_flags(defined: bool, piezoviscous: bool, elastic_piezo: bool, rigid_iso: bool) -> Self {
        let (p, e, r) = (
            usize::from(piezoviscous),
            usize::from(elastic_piezo),
            usize::from(rigid_iso),
        );
        let index = usize::from(defined) * (p * (3 + e) + (1 - p) * (2 - r));
        REGIMES.get(index).copied().unwrap_or(Regime::Dry)
    }
}

/// The regimes by table index: dry, then iso-viscous rigid/elastic, then piezo-viscous.
const REGIMES: [Regime; 5] = [
    Regime::Dry,
    Regime::RigidIsoviscous,
    Regime::ElasticIsoviscous,
    Regime::RigidPiezoviscous,
    Regime::ElasticPiezoviscous,
];

/// ln of the asymptotes' constants: 3, 2.621, 1.287, 1.311.
const LN_RI: f32 = 1.098_612_3;
const LN_EI: f32 = 0.963_556;
const LN_RP: f32 = 0.252_313_9;
const LN_EP: f32 = 0.270_790_2;

/// The regime chart along one contact's load axis. With L fixed (a contact at one speed),
/// each of the chart's comparisons is a threshold in ln M = ln Q − offset, because every
/// asymptote is linear in ln M: the iso-viscous pair swaps at one ln M, the piezo-viscous
/// pair at another, and the piezo-viscous group dominates above the largest of the four
/// crossings between the groups. Three comparisons per contact then classify a roller,
/// instead of the four asymptotes of [`Regime::from_ln_moes`] (the bearing step does this for
/// every roller; the tests check the two agree).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RegimeAxis {
    /// ln Q at and below which the rigid iso-viscous asymptote beats the elastic one.
    rigid_iso_to: f32,
    /// ln Q from which the piezo-viscous group dominates.
    piezoviscous_from: f32,
    /// ln Q from which the elastic piezo-viscous asymptote is the smaller of its pair.
    elastic_piezo_from: f32,
    /// The contact's L and offset are finite.
    defined: bool,
}

impl RegimeAxis {
    /// The axis of a contact with ln M = ln Q − `ln_m_offset` and Moes' ln L.
    pub fn new(ln_m_offset: f32, ln_l: f32) -> Self {
        let l = ln_l;
        // ri ≥ ei ⇔ 0.8·ln M ≤ LN_RI − LN_EI.
        let rigid_iso_to = (LN_RI - LN_EI) / 0.8;
        // ep ≤ rp ⇔ 0.125·ln M ≥ LN_EP − LN_RP + (3/4 − 2/3)·ln L.
        let elastic_piezo_from = 8.0 * (LN_EP - LN_RP) + (2.0 / 3.0) * l;
        // min(rp, ep) ≥ max(ri, ei): all four crossings passed.
        let rp_ri = LN_RI - LN_RP - (2.0 / 3.0) * l;
        let rp_ei = 5.0 * (LN_EI - LN_RP - (2.0 / 3.0) * l);
        let ep_ri = (LN_RI - LN_EP - 0.75 * l) / 0.875;
        let ep_ei = (LN_EI - LN_EP - 0.75 * l) / 0.075;
        let piezoviscous_from = max(max(rp_ri, rp_ei), max(ep_ri, ep_ei));
        Self {
            rigid_iso_to: rigid_iso_to + ln_m_offset,
            piezoviscous_from: piezoviscous_from + ln_m_offset,
            elastic_piezo_from: elastic_piezo_from + ln_m_offset,
            defined: ln_m_offset.is_finite() & ln_l.is_finite(),
        }
    }

    /// The regime at λ = ln Q (Dry for a NaN λ or a non-finite axis). Arithmetic on the
    /// comparisons' flags, as in `from_flags`: choosing between small integers with an `if`
    /// let the compiler branch, and a step's instruction count then depended on its rollers'
    /// regimes (by one instruction; the firmware's determinism test caught it).
    #[inline(always)]
    pub fn at(&self, ln_load: f32) -> Regime {
        Regime::from_flags(
            self.defined & !ln_load.is_nan(),
            ln_load >= self.piezoviscous_from,
            ln_load >= self.elastic_piezo_from,
            ln_load <= self.rigid_iso_to,
        )
    }
}

use crate::math::max;

#[cfg(test)]
mod tests {
    use super::*;
    use libm::logf;

    #[test]
    fn the_load_axis_classifies_like_the_asymptotes() {
        // Over a grid of ln M and ln L covering every region of the chart (M 10⁻³…10⁶,
        // L 0.01…50): the axis agrees with the asymptote comparison wherever the point is not
        // within rounding of a boundary (checked by moving it 10⁻³ either way).
        let mut compared = 0;
        let mut seen = [false; 5];
        for i in 0..=300 {
            let ln_m = -7.0 + 0.07 * i as f32;
            for j in 0..=60 {
                let ln_l = -4.6 + 0.13 * j as f32;
                let offset = 2.5 + 0.01 * j as f32;
                let reference = Regime::from_ln_moes(ln_m, ln_l);
                let axis = RegimeAxis::new(offset, ln_l);
                let near_boundary = Regime::from_ln_moes(ln_m - 1e-3, ln_l) != reference
                    || Regime::from_ln_moes(ln_m + 1e-3, ln_l) != reference;
                if !near_boundary {
                    assert_eq!(
                        axis.at(ln_m + offset),
                        reference,
                        "ln M {ln_m}, ln L {ln_l}"
                    );
                    compared += 1;
                    seen[reference as usize] = true;
                }
            }
        }
        assert!(compared > 15_000, "{compared}");
        assert_eq!(seen, [false, true, true, true, true], "every regime met");
        assert_eq!(RegimeAxis::new(1.0, f32::NAN).at(3.0), Regime::Dry);
        assert_eq!(RegimeAxis::new(1.0, 2.0).at(f32::NAN), Regime::Dry);
    }

    #[test]
    fn corners_of_the_chart() {
        // Heavily loaded steel/oil contact: M = 1000, L = 10 → elastic piezo-viscous.
        assert_eq!(
            Regime::from_ln_moes(logf(1000.0), logf(10.0)),
            Regime::ElasticPiezoviscous
        );
        // Very light load, no pressure–viscosity: M = 0.1, L ≈ 0 → rigid iso-viscous.
        assert_eq!(
            Regime::from_ln_moes(logf(0.1), logf(0.01)),
            Regime::RigidIsoviscous
        );
        // Heavy load, no piezo-viscosity (L small): elastic iso-viscous (soft EHL).
        assert_eq!(
            Regime::from_ln_moes(logf(100.0), logf(0.1)),
            Regime::ElasticIsoviscous
        );
        // Light load, strong piezo-viscosity: rigid piezo-viscous.
        assert_eq!(
            Regime::from_ln_moes(logf(1.0), logf(20.0)),
            Regime::RigidPiezoviscous
        );
        assert_eq!(Regime::from_ln_moes(f32::NAN, 1.0), Regime::Dry);
    }

    #[test]
    fn ep_rp_boundary_is_where_the_two_asymptotes_are_equal() {
        // H_RP = H_EP ⇔ 1.287 L^(2/3) = 1.311 M^(−1/8) L^(3/4) ⇔ M = (1.311/1.287)^8 L^(2/3).
        let l = 15.0f32;
        let m_star = (1.311f32 / 1.287).powi(8) * l.powf(2.0 / 3.0);
        assert_eq!(
            Regime::from_ln_moes(logf(m_star * 1.1), logf(l)),
            Regime::ElasticPiezoviscous
        );
        assert_eq!(
            Regime::from_ln_moes(logf(m_star * 0.9), logf(l)),
            Regime::RigidPiezoviscous
        );
    }
}
