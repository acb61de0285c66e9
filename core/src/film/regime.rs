//! Lubrication regime of a contact from the Moes asymptotes (PHYSICS.md §4, §5.1).
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
        let ri = 1.098_612_3 - ln_m; // ln 3
        let ei = 0.963_556 - 0.2 * ln_m; // ln 2.621
        let rp = 0.252_313_9 + (2.0 / 3.0) * ln_l; // ln 1.287
        let ep = 0.270_790_2 - 0.125 * ln_m + 0.75 * ln_l; // ln 1.311
        let iso = ri.max(ei);
        let piezo = rp.min(ep);
        if !(ln_m.is_finite() && ln_l.is_finite()) {
            Regime::Dry
        } else if piezo >= iso {
            if ep <= rp {
                Regime::ElasticPiezoviscous
            } else {
                Regime::RigidPiezoviscous
            }
        } else if ri >= ei {
            Regime::RigidIsoviscous
        } else {
            Regime::ElasticIsoviscous
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use libm::logf;

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
