//! Building the reference scene from the fixed renderer's scene, so both draw the same thing.
//!
//! Every Q16.16 number is exactly an `f64`, so the reference starts from precisely the values
//! the fixed renderer holds. The one change is that plane normals are normalised again in
//! `f64` (see [`DPlane::new`]); the fixed normal is unit only to within a few 2⁻¹⁶.

use super::{DLight, DObject, DPlane, DScene, DShape, DSphere, DVec3};

impl From<crate::Light> for DLight {
    fn from(light: crate::Light) -> DLight {
        DLight::new(light.position.into(), light.intensity.to_num::<f64>())
    }
}

impl DShape {
    /// The reference twin of a fixed shape, or `None` if it is degenerate in `f64` (a zero
    /// normal or a non-positive radius, which the fixed constructors already refuse).
    #[must_use]
    pub fn from_shape(shape: &crate::Shape) -> Option<DShape> {
        Some(match shape {
            crate::Shape::Plane(p) => {
                DShape::Plane(DPlane::new(p.point().into(), p.normal().into())?)
            }
            crate::Shape::Sphere(s) => {
                let centre = DVec3::from(s.centre());
                DShape::Sphere(DSphere::new(centre, s.radius().to_num::<f64>())?)
            }
        })
    }
}

impl DObject {
    /// The reference twin of a fixed object: the same shape and colour.
    #[must_use]
    pub fn from_object(object: &crate::Object) -> Option<DObject> {
        Some(DObject::new(
            DShape::from_shape(&object.shape)?,
            object.colour,
        ))
    }
}

impl<const N: usize> DScene<N> {
    /// The reference twin of a fixed scene: the same objects in the same order (so hit
    /// indices agree), the same light, ambient and background.
    ///
    /// `None` if an object is degenerate in `f64`, which a validated fixed scene never has.
    #[must_use]
    pub fn from_scene(scene: &crate::Scene<N>) -> Option<DScene<N>> {
        let ambient = scene.ambient().to_num::<f64>();
        let mut out = DScene::new(scene.light().into(), ambient, scene.background());
        for object in scene.objects() {
            // The fixed scene holds at most N objects, so this push cannot fail.
            out.push(DObject::from_object(object)?).ok()?;
        }
        Some(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Fx, Light, Object, Plane, Rgb, Scene, Shape, Sphere, Vec3};

    #[test]
    fn the_twin_has_the_same_objects_light_and_background() {
        let fx = Fx::from_num::<f64>;
        let light = Light::new_unchecked(Vec3::from_ints(-20, 20, 20), fx(0.8));
        let mut scene: Scene<3> = Scene::new(light, fx(0.2), Rgb::new(1, 2, 3)).unwrap();
        let ball = Sphere::new_unchecked(Vec3::new(fx(1.5), fx(-0.5), fx(-18.0)), fx(3.0));
        let ground = Plane::new_unchecked(Vec3::from_ints(0, -4, 0), Vec3::Y);
        scene
            .add(Object {
                shape: Shape::Sphere(ball),
                colour: Rgb::WHITE,
            })
            .unwrap();
        scene
            .add(Object {
                shape: Shape::Plane(ground),
                colour: Rgb::BLACK,
            })
            .unwrap();

        let twin = DScene::from_scene(&scene).unwrap();
        // Q16.16 values convert exactly: 0.8 becomes the Q16.16 number nearest 0.8.
        assert_eq!(
            twin.light(),
            DLight::new(DVec3::new(-20.0, 20.0, 20.0), fx(0.8).to_num())
        );
        assert_eq!(twin.ambient(), fx(0.2).to_num::<f64>());
        assert_eq!(twin.background(), Rgb::new(1, 2, 3));
        let sphere = DSphere::new(DVec3::new(1.5, -0.5, -18.0), 3.0).unwrap();
        let plane = DPlane::new(DVec3::new(0.0, -4.0, 0.0), DVec3::Y).unwrap();
        let expected = [
            DObject::new(sphere.into(), Rgb::WHITE),
            DObject::new(plane.into(), Rgb::BLACK),
        ];
        assert_eq!(twin.objects(), expected);
    }
}
