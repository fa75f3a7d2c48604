//! Impossible parameters are refused with a clear error instead of rendering NaN.

use crate::common;

use common::*;
use essl_lights::*;
use glam::DVec3;

fn spot(inner: f64, outer: f64, cookie: Option<Cookie>) -> LitScene {
    LitScene::new(Shading::Phong, Reflection::BlinnPhong, Material::default()).with_light(
        Light::Spot(SpotLight {
            position: DVec3::new(0.0, 100.0, 0.0),
            direction: DVec3::NEG_Y,
            inner_deg: inner,
            outer_deg: outer,
            edge: EdgeProfile::Smooth,
            cookie,
            color: DVec3::ONE,
            specular: DVec3::ONE,
        }),
    )
}

fn projected(up: DVec3) -> Option<Cookie> {
    Some(Cookie::Projected {
        up,
        image: CookieImage::solid([255; 4]),
    })
}

#[test]
fn cones() {
    let e = spot(30.0, 20.0, None).validate().unwrap_err();
    assert!(matches!(e, LightsError::InnerWiderThanOuter { .. }), "{e}");
    assert!(e.to_string().contains("cosines"), "{e}");
    for bad in [-1.0, 180.5, f64::NAN, f64::INFINITY] {
        assert!(spot(0.0, bad, None).validate().is_err(), "{bad}");
    }
    // inner == outer, 0° and 180° cones are fine (a step, nothing lit, everything lit).
    for (i, o) in [
        (20.0, 20.0),
        (0.0, 0.0),
        (170.0, 180.0),
        (180.0, 180.0),
        (90.0, 90.0),
    ] {
        let s = spot(i, o, None);
        s.validate().unwrap();
        let p = s.prepare().unwrap();
        assert!(p.lights[0].inv_range.is_finite() && (p.lights[0].inv_range as f32).is_finite());
        assert!(p.lights[0].inv_range <= MAX_EDGE_SLOPE);
    }
}

#[test]
fn projector() {
    let e = spot(10.0, 20.0, projected(DVec3::NEG_Y))
        .validate()
        .unwrap_err();
    assert!(
        matches!(e, LightsError::UpParallelToDirection { .. }),
        "{e}"
    );
    let e = spot(10.0, 20.0, projected(DVec3::new(1e-9, 1.0, 0.0)))
        .validate()
        .unwrap_err();
    assert!(
        matches!(e, LightsError::UpParallelToDirection { .. }),
        "{e}"
    );
    let e = spot(0.0, 0.0, projected(DVec3::Z)).validate().unwrap_err();
    assert!(matches!(e, LightsError::CookieConeZero { .. }), "{e}");
    let e = spot(10.0, 20.0, projected(DVec3::ZERO))
        .validate()
        .unwrap_err();
    assert!(matches!(e, LightsError::ZeroVector { .. }), "{e}");
    // A slanted up vector is orthonormalised; a nearly parallel one (1e-5 rad) still works.
    for up in [DVec3::new(0.3, 0.5, -1.0), DVec3::new(1e-5, -1.0, 0.0)] {
        let p = spot(10.0, 120.0, projected(up)).prepare().unwrap();
        let [l, u, f] = p.lights[0].basis;
        for (a, b) in [(l, u), (u, f), (f, l)] {
            assert!(a.dot(b).abs() < 1e-12);
        }
        for v in [l, u, f] {
            assert!((v.length() - 1.0).abs() < 1e-12);
        }
        assert!((l - f.cross(u)).length() < 1e-12);
        assert!(p.lights[0].cookie_scale.is_finite());
    }
    let mut s = spot(10.0, 20.0, projected(DVec3::Z));
    if let Light::Spot(sp) = &mut s.lights[0] {
        if let Some(Cookie::Projected { image, .. }) = &mut sp.cookie {
            image.texels.pop();
        }
    }
    assert!(matches!(s.validate(), Err(LightsError::CookieSize { .. })));
}

#[test]
fn material_and_lights() {
    let mut s = spot(10.0, 20.0, None);
    for (n, ok) in [
        (0.0, true),
        (1.0, true),
        (1e4, true),
        (0.5, false),
        (-1.0, false),
        (1e4 + 1.0, false),
        (f64::NAN, false),
    ] {
        s.material.shininess = n;
        assert_eq!(s.validate().is_ok(), ok, "shininess {n}");
    }
    s.material.shininess = 8.0;
    s.material.diffuse = DVec3::new(0.5, -0.1, 0.0);
    assert!(matches!(
        s.validate(),
        Err(LightsError::NegativeColor { .. })
    ));
    s.material.diffuse = DVec3::ONE;
    s.ambient_light = Some(DVec3::new(f64::INFINITY, 0.0, 0.0));
    assert!(matches!(s.validate(), Err(LightsError::NonFinite { .. })));
    s.ambient_light = None;
    let d = LitScene::new(Shading::Gouraud, Reflection::Lambert, Material::default()).with_light(
        Light::Directional(DirectionalLight {
            direction: DVec3::ZERO,
            color: DVec3::ONE,
            specular: DVec3::ONE,
        }),
    );
    assert!(matches!(d.validate(), Err(LightsError::ZeroVector { .. })));
    let many = scene_of(
        Shading::Phong,
        Reflection::Lambert,
        false,
        &[LightShape::Point; MAX_LIGHTS + 1],
    );
    assert!(matches!(
        many.validate(),
        Err(LightsError::TooManyLights { .. })
    ));
    assert!(generate(&many).is_err());
    let five = scene_of(
        Shading::Phong,
        Reflection::Lambert,
        false,
        &[LightShape::Point; 5],
    );
    let (_, view) = test_view();
    assert!(uber_uniform_values(&five, &view).is_err());
}

#[test]
fn views() {
    let screen = scene_of(
        Shading::Phong,
        Reflection::Phong,
        false,
        &[LightShape::Spot {
            edge: EdgeProfile::Linear,
            cookie: Some(CookieKind::Screen),
        }],
    );
    let (_, mut view) = test_view();
    view.width = 0;
    assert!(matches!(
        uniform_values(&screen, &view),
        Err(LightsError::View(_))
    ));
    let (_, mut view) = test_view();
    view.matrices.model = essl_scene::Mat4([0.0; 16]);
    assert!(matches!(
        uniform_values(&screen, &view),
        Err(LightsError::View(_))
    ));
}
