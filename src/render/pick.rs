//! [`Scene::pick`]: which object is under a pixel, and where.

use crate::error::Error;
use crate::render::camera::Camera;
use crate::scene::Scene;
use crate::scene::hit::SceneHit;

impl<const N: usize, const L: usize> Scene<N, L> {
    /// What the pixel at column `x`, row `y` of `camera`'s picture shows: the hit of its ray
    /// (the object's index, the point, the distance and the normal), or
    /// `None` where it shows the background. This is the hit [`render_row`](crate::render_row)
    /// shades for that pixel.
    ///
    /// ```
    /// use fixray::demo;
    /// let (scene, camera) = (demo::scene(), demo::camera(160, 128)?);
    /// // The bottom row looks down at the ground, object 0; the top row sees sky.
    /// assert_eq!(scene.pick(&camera, 80, 127)?.map(|hit| hit.object()), Some(0));
    /// assert_eq!(scene.pick(&camera, 80, 0)?, None);
    /// assert!(scene.pick(&camera, 160, 0).is_err());
    /// # Ok::<(), fixray::Error>(())
    /// ```
    pub fn pick(&self, camera: &Camera, x: u32, y: u32) -> Result<Option<SceneHit>, Error> {
        camera.check_pixel(x, y)?;
        Ok(self.shoot(&camera.ray(x, y)))
    }
}
