//! Rigid disk attached to one shaft node: mass m, diametral inertia I_d and polar inertia I_p.
//!
//! Its kinetic energy ½m(ẋ² + ẏ²) + ½I_d(θ̇x² + θ̇y²) plus the spin term gives, at the disk's
//! node, the mass diag(m, m, I_d, I_d) and the gyroscopic coupling Ω·I_p·[θ̇y, −θ̇x] in the θx and
//! θy equations (Friswell et al. (2010) §2.3 and ch. 5, rigid disk element).

/// A rigid disk at a node.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidDisk {
    /// Node index the disk sits on.
    pub node: usize,
    /// Mass m (kg).
    pub mass: f64,
    /// Polar moment of inertia I_p about the spin axis (kg·m²).
    pub polar_inertia: f64,
    /// Diametral moment of inertia I_d about a diameter through its centre (kg·m²).
    pub diametral_inertia: f64,
}

impl RigidDisk {
    /// Uniform annular disk of density ρ (kg/m³), outer and inner diameters (m) and axial
    /// thickness h (m): m = ρπ(D² − d²)h/4, I_p = m(D² + d²)/8, I_d = I_p/2 + m h²/12
    /// (thick-ring formulas, Friswell et al. (2010) Example 5.9.1 uses these).
    pub fn annulus(
        node: usize,
        density: f64,
        outer_diameter: f64,
        inner_diameter: f64,
        thickness: f64,
    ) -> RigidDisk {
        let mass = density
            * std::f64::consts::PI
            * (outer_diameter.powi(2) - inner_diameter.powi(2))
            * thickness
            / 4.0;
        let polar_inertia = mass * (outer_diameter.powi(2) + inner_diameter.powi(2)) / 8.0;
        let diametral_inertia = polar_inertia / 2.0 + mass * thickness.powi(2) / 12.0;
        RigidDisk {
            node,
            mass,
            polar_inertia,
            diametral_inertia,
        }
    }
}
