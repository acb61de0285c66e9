//! [`BearingOutput`] as `nalgebra` vectors and matrices, for host integrators that assemble
//! their equations of motion with nalgebra (feature `nalgebra`).
//!
//! Copies only: the step itself keeps its arrays, and none of these conversions allocates
//! (every type is statically sized; nalgebra is built without `std` or `alloc`, so the core
//! stays `no_std` with the feature on). The roller loads come as an `SVector<f32, Z>`, Z being
//! the bearing's roller count; a `DVector` would need `alloc`.
//!
//! Coordinates are the output's: (x, y, tilt about x, tilt about y) of the inner race; the
//! matrices are the output's row-major arrays, entry (i, j) = `array[i][j]`.

use ::nalgebra::{Matrix2, Matrix4, SVector, Vector2};

use super::output::BearingOutput;

impl<const Z: usize> BearingOutput<Z> {
    /// Force of the rollers on the inner race (F_x, F_y) (N).
    ///
    /// ```
    /// use bearing_core::BearingOutput;
    /// use nalgebra::Vector2;
    ///
    /// let mut out = BearingOutput::<17>::ZERO;
    /// out.totals.force_n = [120.0, -4500.0];
    /// assert_eq!(out.force_vector_n(), Vector2::new(120.0, -4500.0));
    /// ```
    pub fn force_vector_n(&self) -> Vector2<f32> {
        Vector2::from(self.force_n)
    }

    /// Moment of the rollers on the inner race (M_x, M_y) (N·m).
    ///
    /// ```
    /// use bearing_core::BearingOutput;
    /// use nalgebra::Vector2;
    ///
    /// let mut out = BearingOutput::<17>::ZERO;
    /// out.totals.moment_nm = [0.5, -1.25];
    /// assert_eq!(out.moment_vector_nm(), Vector2::new(0.5, -1.25));
    /// ```
    pub fn moment_vector_nm(&self) -> Vector2<f32> {
        Vector2::from(self.moment_nm)
    }

    /// Stiffness −∂(F_x, F_y, M_x, M_y)/∂(x, y, tilt_x, tilt_y): N/m in the radial block,
    /// N between force and tilt or moment and displacement, N·m/rad in the tilt block.
    ///
    /// ```
    /// use bearing_core::BearingOutput;
    /// use nalgebra::{Matrix4, Vector4};
    ///
    /// let mut out = BearingOutput::<17>::ZERO;
    /// out.totals.stiffness[0] = [2.0e8, 1.0e6, 0.0, 3.0e5];
    /// out.totals.stiffness[3] = [3.0e5, 0.0, 0.0, 4.0e3];
    /// let k: Matrix4<f32> = out.stiffness_matrix();
    /// assert_eq!(k[(0, 1)], 1.0e6);
    /// assert_eq!(k[(3, 0)], 3.0e5);
    /// // The force change of a small displacement of the inner race: ΔF = −K·Δq.
    /// let dq = Vector4::new(1.0e-6, 0.0, 0.0, 0.0);
    /// assert_eq!(-(k * dq)[0], -200.0);
    /// ```
    pub fn stiffness_matrix(&self) -> Matrix4<f32> {
        let [[k00, k01, k02, k03], [k10, k11, k12, k13], [k20, k21, k22, k23], [k30, k31, k32, k33]] =
            self.stiffness;
        // `Matrix4::new` takes its entries row by row.
        Matrix4::new(
            k00, k01, k02, k03, k10, k11, k12, k13, k20, k21, k22, k23, k30, k31, k32, k33,
        )
    }

    /// The radial block −∂(F_x, F_y)/∂(x, y) of [`BearingOutput::stiffness_matrix`] (N/m).
    ///
    /// ```
    /// use bearing_core::BearingOutput;
    /// use nalgebra::Matrix2;
    ///
    /// let mut out = BearingOutput::<17>::ZERO;
    /// out.totals.stiffness[0] = [2.0e8, 1.0e6, 7.0, 7.0];
    /// out.totals.stiffness[1] = [1.5e6, 3.0e8, 7.0, 7.0];
    /// assert_eq!(
    ///     out.radial_stiffness_matrix_n_per_m(),
    ///     Matrix2::new(2.0e8, 1.0e6, 1.5e6, 3.0e8)
    /// );
    /// ```
    pub fn radial_stiffness_matrix_n_per_m(&self) -> Matrix2<f32> {
        let [[k00, k01], [k10, k11]] = self.radial_stiffness_n_per_m();
        Matrix2::new(k00, k01, k10, k11)
    }

    /// Damping −∂(F_x, F_y)/∂(ẋ, ẏ) (N·s/m).
    ///
    /// ```
    /// use bearing_core::BearingOutput;
    /// use nalgebra::Matrix2;
    ///
    /// let mut out = BearingOutput::<17>::ZERO;
    /// out.totals.damping_n_s_per_m = [[400.0, 10.0], [20.0, 800.0]];
    /// assert_eq!(out.damping_matrix_n_s_per_m(), Matrix2::new(400.0, 10.0, 20.0, 800.0));
    /// ```
    pub fn damping_matrix_n_s_per_m(&self) -> Matrix2<f32> {
        let [[c00, c01], [c10, c11]] = self.damping_n_s_per_m;
        Matrix2::new(c00, c01, c10, c11)
    }

    /// Every roller's contact load Q_j (N), roller j at index j.
    ///
    /// ```
    /// use bearing_core::BearingOutput;
    /// use nalgebra::SVector;
    ///
    /// let mut out = BearingOutput::<3>::ZERO;
    /// out.rollers[1].load_n = 900.0;
    /// let loads: SVector<f32, 3> = out.roller_loads_vector_n();
    /// assert_eq!(loads, SVector::<f32, 3>::new(0.0, 900.0, 0.0));
    /// ```
    pub fn roller_loads_vector_n(&self) -> SVector<f32, Z> {
        SVector::from(self.rollers.map(|r| r.load_n))
    }
}

#[cfg(test)]
mod tests {
    use crate::{Bearing, BearingDesign, FilmKind, OperatingState};

    /// A loaded, lubricated hub-motor bearing (docs/physics.md §6.2: d_m 60 mm, D 8.8 mm × 15 mm,
    /// 17 rollers; here uncrowned with 5 µm clearance): every nalgebra view holds the output's
    /// numbers at the output's places, and the views agree with each other.
    #[test]
    fn views_of_a_hub_motor_step_hold_the_output() {
        let params = BearingDesign {
            crown_scale: 0.0,
            radial_clearance_m: 5.0e-6,
            ..BearingDesign::HUB_MOTOR
        }
        .params()
        .unwrap();
        let mut bearing = Bearing::<17, 10>::new(params, FilmKind::Regression).unwrap();
        bearing.set_cage_angle(0.3).unwrap();
        // Displaced 12 µm along x and 4 µm along −y, tilted, moving, at 3000 rpm.
        let state = OperatingState::new(
            [12.0e-6, -4.0e-6],
            [0.01, -0.02],
            [1.0e-4, 0.0],
            3000.0 * core::f32::consts::PI / 30.0,
        )
        .unwrap();
        let out = *bearing.settle(&state, 4).unwrap();
        assert!(out.force_n[0] < -100.0, "loaded along x: {:?}", out.force_n);

        let force = out.force_vector_n();
        let moment = out.moment_vector_nm();
        assert_eq!((force.x, force.y), (out.force_n[0], out.force_n[1]));
        assert_eq!((moment.x, moment.y), (out.moment_nm[0], out.moment_nm[1]));

        let k = out.stiffness_matrix();
        let c = out.damping_matrix_n_s_per_m();
        for (i, row) in out.stiffness.iter().enumerate() {
            for (j, &value) in row.iter().enumerate() {
                assert_eq!(k[(i, j)].to_bits(), value.to_bits(), "stiffness ({i}, {j})");
            }
        }
        for (i, row) in out.damping_n_s_per_m.iter().enumerate() {
            for (j, &value) in row.iter().enumerate() {
                assert_eq!(c[(i, j)].to_bits(), value.to_bits(), "damping ({i}, {j})");
            }
        }
        // The radial matrix is the top-left block of the full one; a loaded bearing resists
        // a radial displacement (positive diagonal).
        assert_eq!(
            out.radial_stiffness_matrix_n_per_m(),
            k.fixed_view::<2, 2>(0, 0).into_owned()
        );
        assert!(k[(0, 0)] > 0.0 && k[(1, 1)] > 0.0);

        let loads = out.roller_loads_vector_n();
        assert_eq!(loads.len(), 17);
        for (j, roller) in out.rollers.iter().enumerate() {
            assert_eq!(loads[j].to_bits(), roller.load_n.to_bits(), "roller {j}");
        }
        assert_eq!(loads.max(), out.max_roller_load_n());
    }
}
