//! Building the reference scene from the fixed renderer's scene, so both draw the same thing.
//!
//! Every Q16.16 number is exactly an `f64`, so the reference starts from precisely the values
//! the fixed renderer holds (in `f32`, from the nearest `f32` to each: 24 bits hold any Q16.16
//! number below 256 exactly). The one change is that plane normals are normalised again in
//! `f64` (see [`DPlane::new`]); the fixed normal is unit only to within a few 2⁻¹⁶. Scaling
//! all three components by one positive number keeps their order, so a plane's `(u, v)` axes
//! ([`DPlane::coords`]) are the ones the fixed plane chose.

use super::{
    DChecker, DLight, DMaterial, DObject, DPlane, DRefraction, DScene, DShape, DSphere, DVec3, Real,
};
use fixray::Fx;

/// The Q16.16 number in `F`: exact in `f64`, the nearest `f32` in `f32`.
fn f<F: Real>(x: Fx) -> F {
    F::from_f64(x.to_num::<f64>())
}

impl<F: Real> From<fixray::Light> for DLight<F> {
    fn from(light: fixray::Light) -> Self {
        DLight::new(light.position().into(), f(light.intensity()))
    }
}

impl<F: Real> From<fixray::Checker> for DChecker<F> {
    fn from(checker: fixray::Checker) -> Self {
        DChecker {
            size: f(checker.size()),
            other: checker.other(),
        }
    }
}

impl<F: Real> From<fixray::Material> for DMaterial<F> {
    fn from(m: fixray::Material) -> Self {
        DMaterial {
            colour: m.colour(),
            diffuse: f(m.diffuse()),
            specular: f(m.specular()),
            shininess: m.shininess(),
            reflect: f(m.reflect()),
            checker: m.checker().map(DChecker::from),
            refract: m.refraction().map(|r| DRefraction {
                index: f(r.index()),
                weight: f(r.weight()),
                fresnel: r.fresnel(),
            }),
        }
    }
}

impl<F: Real> DShape<F> {
    /// The reference twin of a fixed shape, or `None` if it is degenerate in `f64` (a zero
    /// normal, empty bounds or a non-positive radius, which the fixed constructors refuse).
    #[must_use]
    pub fn from_shape(shape: &fixray::Shape) -> Option<Self> {
        Some(match shape {
            fixray::Shape::Plane(p) => {
                let plane = DPlane::new(p.point().into(), p.normal().into())?;
                DShape::Plane(match p.bounds() {
                    Some([min, max]) => plane.bounded(min.map(f), max.map(f))?,
                    None => plane,
                })
            }
            fixray::Shape::Sphere(s) => {
                let centre = DVec3::from(s.centre());
                DShape::Sphere(DSphere::new(centre, f(s.radius()))?)
            }
        })
    }
}

impl<F: Real> DObject<F> {
    /// The reference twin of a fixed object: the same shape and material.
    #[must_use]
    pub fn from_object(object: &fixray::Object) -> Option<Self> {
        Some(DObject::new(
            DShape::from_shape(&object.shape)?,
            object.material.into(),
        ))
    }
}

impl<const N: usize, const L: usize, F: Real> DScene<N, L, F> {
    /// The reference twin of a fixed scene: the same objects in the same order (so hit
    /// indices agree), the same lights, ambient, background, shadow switch and mirror depth.
    ///
    /// `None` if an object is degenerate in `f64`, which a validated fixed scene never has.
    #[must_use]
    pub fn from_scene(scene: &fixray::Scene<N, L>) -> Option<Self> {
        let mut out = DScene::new(f(scene.ambient()), scene.background());
        out.set_shadows(scene.shadows());
        out.set_depth(scene.depth());
        // The capacities are the fixed scene's, so neither kind of push can fail.
        for light in scene.lights() {
            out.push_light((*light).into()).ok()?;
        }
        for object in scene.objects() {
            out.push(DObject::from_object(object)?).ok()?;
        }
        Some(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use fixray::{Background, Light, Material, Object, Plane, Rgb, Scene, Shape, Sphere};

    #[test]
    fn the_twin_has_the_same_objects_lights_and_settings() {
        let fx = Fx::from_num::<f64>;
        let light = Light::new([-20.0, 20.0, 20.0], 0.8).unwrap();
        let sky = Background {
            top: Rgb::new(1, 2, 3),
            bottom: Rgb::new(4, 5, 6),
        };
        let mut scene: Scene<3, 2> = Scene::new(light, 0.2, sky).unwrap();
        scene
            .add_light(Light::new([5.0, 5.0, 5.0], 3.5).unwrap())
            .unwrap();
        scene.set_shadows(false);
        scene.set_depth(7);
        let ball = Sphere::new([1.5, -0.5, -18.0], 3.0).unwrap();
        let shiny = Material::new(Rgb::WHITE, 0.6, 0.3, 50, 0.1).unwrap();
        scene
            .add(Object {
                shape: Shape::Sphere(ball),
                material: shiny,
            })
            .unwrap();
        let ground = Plane::new([0.0, -4.0, 0.0], [0.0, 1.0, 0.0])
            .unwrap()
            .bounded([-10.0, -30.0], [10.0, -10.25])
            .unwrap();
        let board = Material::matte(Rgb::BLACK)
            .with_checker(1.5, Rgb::new(7, 8, 9))
            .unwrap();
        scene.add_plane(ground, board).unwrap();

        let twin = DScene::from_scene(&scene).unwrap();
        // Q16.16 values convert exactly: 0.8 becomes the Q16.16 number nearest 0.8.
        assert_eq!(
            twin.lights(),
            [
                DLight::new(DVec3::new(-20.0, 20.0, 20.0), Fx::from_num(0.8f32).to_num()),
                DLight::new(DVec3::new(5.0, 5.0, 5.0), 3.5),
            ]
        );
        assert_eq!(twin.ambient(), fx(0.2).to_num::<f64>());
        assert_eq!(twin.background(), sky);
        assert_eq!((twin.shadows(), twin.depth()), (false, 7));
        let sphere = DSphere::new(DVec3::new(1.5, -0.5, -18.0), 3.0).unwrap();
        let plane = DPlane::new(DVec3::new(0.0, -4.0, 0.0), DVec3::Y)
            .unwrap()
            .bounded([-10.0, -30.0], [10.0, -10.25])
            .unwrap();
        let shiny = DMaterial {
            colour: Rgb::WHITE,
            diffuse: fx(0.6).to_num(),
            specular: fx(0.3).to_num(),
            shininess: 50,
            reflect: fx(0.1).to_num(),
            checker: None,
            refract: None,
        };
        let board = DMaterial {
            checker: Some(DChecker {
                size: 1.5,
                other: Rgb::new(7, 8, 9),
            }),
            ..DMaterial::matte(Rgb::BLACK)
        };
        let expected = [
            DObject::new(sphere.into(), shiny),
            DObject::new(plane.into(), board),
        ];
        assert_eq!(twin.objects(), expected);
    }

    #[test]
    fn glass_keeps_its_index_weight_and_fresnel_choice() {
        let glass = Material::matte(Rgb::WHITE)
            .with_refraction(1.5, 0.8)
            .unwrap()
            .with_fresnel();
        let twin = DMaterial::<f64>::from(glass);
        assert_eq!(
            twin.refract,
            Some(DRefraction {
                index: 1.5,
                weight: Fx::from_num(0.8f32).to_num(),
                fresnel: true,
            })
        );
        assert_eq!(
            DMaterial::<f64>::from(Material::matte(Rgb::WHITE)).refract,
            None
        );
    }

    #[test]
    fn the_demo_scene_converts() {
        let demo = fixray::demo::scene();
        let twin: DScene<8> = DScene::from_scene(&demo).unwrap();
        assert_eq!(twin.objects().len(), demo.objects().len());
        assert_eq!(twin.lights().len(), demo.lights().len());
        assert_eq!(twin.shadows(), demo.shadows());
    }
}
