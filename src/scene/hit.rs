//! [`SceneHit`]: the nearest hit in a scene, and which object it is on.

use crate::geometry::hit::Hit;

/// The nearest hit of a ray in a [`Scene`](crate::Scene): the [`Hit`] on a shape, and the
/// index of the object it is on, as [`Scene::add`](crate::Scene::add) returned it.
///
/// ```
/// use fixray::{Light, Ray, Rgb, Scene, Sphere, Vec3};
/// let mut scene: Scene<1> = Scene::new(Light::new([0.0, 10.0, 0.0], 1.0)?, 0.2, Rgb::BLACK)?;
/// let ball = scene.add_sphere(Sphere::new([0.0, 0.0, -10.0], 2.0)?, Rgb::WHITE)?;
/// let seen = scene.shoot(&Ray::new(Vec3::ZERO, -Vec3::Z)?).unwrap();
/// assert_eq!(seen.object(), ball);
/// assert_eq!(seen.hit().point(), Vec3::from_ints(0, 0, -8));
/// # Ok::<(), fixray::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SceneHit {
    pub(crate) hit: Hit,
    pub(crate) object: usize,
}

impl SceneHit {
    /// The index of the object hit.
    #[must_use]
    pub const fn object(&self) -> usize {
        self.object
    }

    /// Where the ray met that object's shape: the distance, the point and the normal (on the
    /// side the ray came from, as for every [`Hit`]).
    #[must_use]
    pub const fn hit(&self) -> Hit {
        self.hit
    }
}
