//! Geometry: the chapter's [`Ray`] (Eq. 4.1), the [`Plane`] (Eq. 4.2) and the [`Sphere`]
//! (section 4.4), each a pure intersection function returning a [`Hit`], and [`Shape`], either
//! of the two.

pub(crate) mod hit;
pub(crate) mod plane;
pub(crate) mod ray;
pub(crate) mod refract;
pub(crate) mod shape;
pub(crate) mod sphere;

pub use hit::Hit;
pub use plane::Plane;
pub use ray::Ray;
pub use shape::Shape;
pub use sphere::Sphere;
