//! Timoshenko shaft element: mass, stiffness and gyroscopic matrices of a rotating,
//! possibly hollow, circular beam segment with shear deformation and rotary inertia.
//!
//! Degrees of freedom (4 per node, 8 per element), in this order at each node:
//! `x`, `y` (lateral displacements, m) and `θx`, `θy` (rotations about the x and y axes, rad).
//! The shaft axis is z and the shaft spins at Ω about +z. With the right-hand rule a positive
//! `θy` turns the axis towards +x and a positive `θx` towards −y, so without shear
//! `θy = dx/dz` and `θx = −dy/dz` — the convention of Friswell, Penny, Garvey & Lees,
//! *Dynamics of Rotating Machines* (2010), §5.4 (their u, v, θ, ψ).
//!
//! Interpolation: the "interdependent" Timoshenko shape functions (cubic deflection, quadratic
//! rotation, both depending on the shear parameter Φ = 12EI/(κGAL²)) of Friedman & Kosmatka,
//! *An improved two-node Timoshenko beam finite element*, Comput. Struct. 47 (1993) 473–481,
//! which are the functions behind the Timoshenko shaft element of Friswell et al. (2010) ch. 5
//! (closed-form element matrices there; Nelson, *A finite rotating shaft element using Timoshenko
//! beam theory*, J. Mech. Des. 102 (1980) 793–803, the original rotating version). The matrices
//! here are the exact integrals of the energy expressions
//!
//! * kinetic, translational: ½ ρA ∫ (ẋ² + ẏ²) dz
//! * kinetic, rotary:       ½ ρI ∫ (θ̇x² + θ̇y²) dz
//! * gyroscopic:            Ω ρIp ∫ (θ̇x θy − θ̇y θx)… giving the skew term ΩG q̇ (G\[θx,θy\] = +ρIp)
//! * bending strain:        ½ EI ∫ (θx'² + θy'²) dz
//! * shear strain:          ½ κGA ∫ ((x' − θy)² + (y' + θx)²) dz
//!
//! computed by 4-point Gauss–Legendre quadrature, which is exact because every integrand is a
//! polynomial of degree ≤ 6 in the element coordinate.

use nalgebra::SMatrix;

/// 8×8 element matrix.
pub type ElementMatrix = SMatrix<f64, 8, 8>;

/// Isotropic, linear-elastic shaft material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    /// Young's modulus E (Pa).
    pub youngs_modulus: f64,
    /// Shear modulus G (Pa).
    pub shear_modulus: f64,
    /// Density ρ (kg/m³).
    pub density: f64,
}

impl Material {
    /// Poisson's ratio from E and G (isotropic: G = E / (2(1 + ν))).
    pub fn poisson_ratio(&self) -> f64 {
        self.youngs_modulus / (2.0 * self.shear_modulus) - 1.0
    }
}

/// One uniform shaft element between two nodes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TimoshenkoElement {
    /// Element length L (m).
    pub length: f64,
    /// Outer diameter (m).
    pub outer_diameter: f64,
    /// Inner (bore) diameter, 0 for a solid shaft (m).
    pub inner_diameter: f64,
    /// Material of the element.
    pub material: Material,
}

/// The three matrices of one element, in the DOF order documented at the module top.
#[derive(Debug, Clone)]
pub struct ElementMatrices {
    /// Consistent mass matrix (kg, kg·m, kg·m²).
    pub mass: ElementMatrix,
    /// Stiffness matrix, bending + shear (N/m, N, N·m).
    pub stiffness: ElementMatrix,
    /// Gyroscopic matrix per unit spin speed: the equation holds Ω·G·q̇ (kg·m² per rad).
    pub gyroscopic: ElementMatrix,
}

/// Gauss–Legendre points and weights on [0, 1] (4 points: exact to degree 7).
const GAUSS_4: [(f64, f64); 4] = [
    (0.069_431_844_202_973_71, 0.173_927_422_568_726_93),
    (0.330_009_478_207_571_87, 0.326_072_577_431_273_07),
    (0.669_990_521_792_428_1, 0.326_072_577_431_273_07),
    (0.930_568_155_797_026_3, 0.173_927_422_568_726_93),
];

impl TimoshenkoElement {
    /// Cross-section area A (m²).
    pub fn area(&self) -> f64 {
        std::f64::consts::PI / 4.0 * (self.outer_diameter.powi(2) - self.inner_diameter.powi(2))
    }

    /// Diametral second moment of area I (m⁴); the polar one is 2I.
    pub fn second_moment(&self) -> f64 {
        std::f64::consts::PI / 64.0 * (self.outer_diameter.powi(4) - self.inner_diameter.powi(4))
    }

    /// Shear coefficient κ of a hollow circular section, Cowper, *The shear coefficient in
    /// Timoshenko's beam theory*, J. Appl. Mech. 33 (1966) 335–340, Table 1 (the form Friswell et
    /// al. (2010) ch. 5 quote): κ = 6(1+ν)(1+r²)² / [(7+6ν)(1+r²)² + (20+12ν)r²],
    /// r = inner/outer diameter (solid: 6(1+ν)/(7+6ν)).
    pub fn shear_coefficient(&self) -> f64 {
        let nu = self.material.poisson_ratio();
        let r = self.inner_diameter / self.outer_diameter;
        let s = (1.0 + r * r).powi(2);
        6.0 * (1.0 + nu) * s / ((7.0 + 6.0 * nu) * s + (20.0 + 12.0 * nu) * r * r)
    }

    /// Shear deformation parameter Φ = 12EI/(κGAL²) (dimensionless).
    pub fn shear_parameter(&self) -> f64 {
        12.0 * self.material.youngs_modulus * self.second_moment()
            / (self.shear_coefficient()
                * self.material.shear_modulus
                * self.area()
                * self.length.powi(2))
    }

    /// Element mass (kg).
    pub fn mass(&self) -> f64 {
        self.material.density * self.area() * self.length
    }

    /// The mass, stiffness and gyroscopic matrices (module docs give the energy expressions).
    pub fn matrices(&self) -> ElementMatrices {
        let l = self.length;
        let phi = self.shear_parameter();
        let e = self.material.youngs_modulus;
        let rho = self.material.density;
        let a = self.area();
        let i = self.second_moment();
        let kga = self.shear_coefficient() * self.material.shear_modulus * a;

        let mut mass = ElementMatrix::zeros();
        let mut stiffness = ElementMatrix::zeros();
        let mut gyroscopic = ElementMatrix::zeros();
        for (xi, w) in GAUSS_4 {
            let f = Fields::at(xi, l, phi);
            let dz = w * l;
            for r in 0..8 {
                for c in 0..8 {
                    mass[(r, c)] += dz
                        * (rho * a * (f.x[r] * f.x[c] + f.y[r] * f.y[c])
                            + rho * i * (f.tx[r] * f.tx[c] + f.ty[r] * f.ty[c]));
                    stiffness[(r, c)] += dz
                        * (e * i * (f.dtx[r] * f.dtx[c] + f.dty[r] * f.dty[c])
                            + kga * (f.gx[r] * f.gx[c] + f.gy[r] * f.gy[c]));
                    // Polar moment of area = 2I.
                    gyroscopic[(r, c)] +=
                        dz * rho * 2.0 * i * (f.tx[r] * f.ty[c] - f.ty[r] * f.tx[c]);
                }
            }
        }
        ElementMatrices {
            mass,
            stiffness,
            gyroscopic,
        }
    }
}

/// Interpolation rows at one point: each field = row · q_element.
struct Fields {
    x: [f64; 8],
    y: [f64; 8],
    tx: [f64; 8],
    ty: [f64; 8],
    dtx: [f64; 8],
    dty: [f64; 8],
    gx: [f64; 8],
    gy: [f64; 8],
}

impl Fields {
    /// Planar Timoshenko shape functions (Friedman & Kosmatka 1993) for w(ξ) and the section
    /// rotation φ(ξ) over the planar DOFs [w1, φ1, w2, φ2], mapped to the two planes:
    /// x–z plane: w = x, φ = θy; y–z plane: w = y, φ = −θx.
    fn at(xi: f64, l: f64, phi: f64) -> Fields {
        let d = 1.0 + phi;
        let (x2, x3) = (xi * xi, xi * xi * xi);
        // Deflection shape functions N and their z-derivatives.
        let n = [
            (2.0 * x3 - 3.0 * x2 - phi * xi + 1.0 + phi) / d,
            l * (x3 - (2.0 + phi / 2.0) * x2 + (1.0 + phi / 2.0) * xi) / d,
            -(2.0 * x3 - 3.0 * x2 - phi * xi) / d,
            l * (x3 - (1.0 - phi / 2.0) * x2 - (phi / 2.0) * xi) / d,
        ];
        let dn = [
            (6.0 * x2 - 6.0 * xi - phi) / (d * l),
            (3.0 * x2 - (4.0 + phi) * xi + 1.0 + phi / 2.0) / d,
            -(6.0 * x2 - 6.0 * xi - phi) / (d * l),
            (3.0 * x2 - (2.0 - phi) * xi - phi / 2.0) / d,
        ];
        // Rotation shape functions and their z-derivatives.
        let r = [
            6.0 * (x2 - xi) / (d * l),
            (3.0 * x2 - (4.0 + phi) * xi + 1.0 + phi) / d,
            -6.0 * (x2 - xi) / (d * l),
            (3.0 * x2 - (2.0 - phi) * xi) / d,
        ];
        let dr = [
            6.0 * (2.0 * xi - 1.0) / (d * l * l),
            (6.0 * xi - 4.0 - phi) / (d * l),
            -6.0 * (2.0 * xi - 1.0) / (d * l * l),
            (6.0 * xi - 2.0 + phi) / (d * l),
        ];
        let mut f = Fields {
            x: [0.0; 8],
            y: [0.0; 8],
            tx: [0.0; 8],
            ty: [0.0; 8],
            dtx: [0.0; 8],
            dty: [0.0; 8],
            gx: [0.0; 8],
            gy: [0.0; 8],
        };
        // Planar DOF k of the x–z plane: (node, local) = x1, θy1, x2, θy2 → element indices.
        let xz = [0usize, 3, 4, 7];
        // y–z plane planar DOFs y1, −θx1, y2, −θx2: element index and sign.
        let yz = [(1usize, 1.0), (2, -1.0), (5, 1.0), (6, -1.0)];
        for k in 0..4 {
            let ix = xz[k];
            f.x[ix] = n[k];
            f.ty[ix] = r[k];
            f.dty[ix] = dr[k];
            f.gx[ix] = dn[k] - r[k];
            let (iy, s) = yz[k];
            f.y[iy] = s * n[k];
            // θx = −φ_y, shear strain γ_yz = y' + θx = w' − φ.
            f.tx[iy] = -s * r[k];
            f.dtx[iy] = -s * dr[k];
            f.gy[iy] = s * (dn[k] - r[k]);
        }
        f
    }
}
