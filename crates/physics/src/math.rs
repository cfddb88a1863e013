//! The numeric types every module shares (SI units, `f64`, world frame right-handed, z up).

/// 3-vector of `f64` (positions in m, forces in N, …).
pub type Vec3 = nalgebra::Vector3<f64>;
/// 3×3 matrix of `f64` (inertia tensors in kg·m², rotations).
pub type Mat3 = nalgebra::Matrix3<f64>;
/// Unit quaternion: a body's orientation, principal frame → world frame.
pub type Rotation = nalgebra::UnitQuaternion<f64>;

/// Corners `(low, high)` of the axis-aligned box around `points` (componentwise minimum and
/// maximum); `(+∞, −∞)` when there are none.
pub fn bounding_box(points: impl IntoIterator<Item = Vec3>) -> (Vec3, Vec3) {
    points.into_iter().fold((Vec3::repeat(f64::INFINITY), Vec3::repeat(f64::NEG_INFINITY)), |(low, high), p| {
        (low.inf(&p), high.sup(&p))
    })
}
