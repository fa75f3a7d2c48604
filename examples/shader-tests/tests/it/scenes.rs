//! Uploading through the generated bindings draws the shared scenes exactly as `essl render`
//! does. For each scene, `essl_gl::scene::render_scene` (what `essl render` runs) draws the
//! reference; then the same scene is set up with its `uniforms` left out, and the values go in
//! through the scene program's typed `Uniforms` and `Program::upload`, filled field by field
//! from the scene's numbers. A struct literal names every field, so a uniform added to or
//! renamed in a scene's shader stops this file from compiling.

#[cfg(essl_scenes)]
mod typed {

    use essl_gl::scene::{render_scene, SceneRenderer};
    use essl_scene::{Scene, UniformType, UploadValues};
    use shader_tests::scenes;

    /// A value of the scene's `uniforms`, fitted to a field's Rust type.
    trait FromScene: Sized {
        fn from_scene(scene: &Scene, name: &str) -> Self;
    }

    fn values(scene: &Scene, name: &str, ty: UniformType) -> Vec<f32> {
        let uniform = scene
            .uniform(name)
            .unwrap_or_else(|| panic!("the scene sets no {name}"));
        match uniform
            .upload(ty, 1)
            .unwrap_or_else(|e| panic!("{name}: {e}"))
        {
            UploadValues::F32(v) => v,
            other => panic!("{name}: {other:?}"),
        }
    }

    impl FromScene for f32 {
        fn from_scene(scene: &Scene, name: &str) -> f32 {
            values(scene, name, UniformType::Float(1))[0]
        }
    }

    impl<const N: usize> FromScene for [f32; N] {
        fn from_scene(scene: &Scene, name: &str) -> [f32; N] {
            let ty = match N {
                2..=4 => UniformType::Float(N as u8),
                9 => UniformType::Mat3,
                16 => UniformType::Mat4,
                _ => panic!("{name}: no GLSL type has {N} floats"),
            };
            values(scene, name, ty).try_into().expect("the type's size")
        }
    }

    fn get<T: FromScene>(scene: &Scene, name: &str) -> T {
        T::from_scene(scene, name)
    }

    /// The texture unit of a sampler of the scene.
    fn unit(scene: &Scene, name: &str) -> i32 {
        scene
            .texture(name)
            .map(|t| t.unit as i32)
            .expect("the scene's texture")
    }

    /// Draws `scene` with its uniforms set by `upload` (through typed bindings) and compares
    /// the frame with `render_scene`'s, pixel for pixel.
    fn same_as_render(
        name: &str,
        upload: impl FnOnce(&mut essl_gl::Context, essl_gl::Program, &Scene),
        attributes: &[(&str, u32)],
    ) {
        let Some(dir) = essl_testdata::scenes() else {
            return;
        };
        let scene = Scene::load(dir.join(format!("{name}.json"))).unwrap();
        if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
            std::env::set_var("XDG_RUNTIME_DIR", std::env::temp_dir());
        }
        let reference = match render_scene(&scene, 0) {
            Ok(r) => r.image,
            Err(essl_gl::scene::SceneRenderError::Context(e)) => {
                return essl_testdata::adapter_missing(&e);
            }
            Err(e) => panic!("{name}: {e}"),
        };
        let mut bare = scene.clone();
        bare.uniforms.clear();
        let mut renderer = SceneRenderer::new(&bare).unwrap();
        let program = renderer.program();
        // The generated locations are the ones essl-gl's linker gives.
        for &(attribute, location) in attributes {
            let got = renderer.context().get_attrib_location(program, attribute);
            assert_eq!(got, location as i32, "{name}: {attribute}");
        }
        // Without the uniforms the frame differs: what follows tests the upload.
        renderer.frame();
        let unset = renderer.read_image().unwrap();
        let diff = essl_scene::compare(&unset, &reference, 0).unwrap();
        assert!(
            !diff.all_within(),
            "{name}: the scene draws the same without uniforms"
        );
        upload(renderer.context(), program, &scene);
        renderer.frame();
        let typed = renderer.read_image().unwrap();
        let diff = essl_scene::compare(&typed, &reference, 0).unwrap();
        assert!(
            diff.all_within(),
            "{name}: {} pixels differ from render_scene's",
            diff.outside_tolerance()
        );
    }

    #[test]
    fn gouraud_lambert() {
        for name in ["gouraud-lambert", "gouraud-lambert-coarse"] {
            let upload = |gl: &mut essl_gl::Context, program, scene: &Scene| {
                use scenes::gouraud_lambert as p;
                let u = p::Uniforms {
                    uModelViewMatrix: get(scene, "uModelViewMatrix"),
                    uNormalMatrix: get(scene, "uNormalMatrix"),
                    uProjectionMatrix: get(scene, "uProjectionMatrix"),
                    uLightDirection: get(scene, "uLightDirection"),
                    uLightDiffuse: get(scene, "uLightDiffuse"),
                    uMaterialDiffuse: get(scene, "uMaterialDiffuse"),
                };
                p::Program::from_linked(gl, program).upload(gl, &u);
            };
            same_as_render(name, upload, scenes::gouraud_lambert::ATTRIBUTES);
        }
    }

    #[test]
    fn phong_positional() {
        let upload = |gl: &mut essl_gl::Context, program, scene: &Scene| {
            use scenes::phong_positional as p;
            let u = p::Uniforms {
                uModelViewMatrix: get(scene, "uModelViewMatrix"),
                uNormalMatrix: get(scene, "uNormalMatrix"),
                uProjectionMatrix: get(scene, "uProjectionMatrix"),
                uLightPosition: get(scene, "uLightPosition"),
                uMaterialAmbientColor: get(scene, "uMaterialAmbientColor"),
                uMaterialDiffuseColor: get(scene, "uMaterialDiffuseColor"),
                uMaterialSpecularColor: get(scene, "uMaterialSpecularColor"),
                uLightAmbientColor: get(scene, "uLightAmbientColor"),
                uLightDiffuseColor: get(scene, "uLightDiffuseColor"),
                uLightSpecularColor: get(scene, "uLightSpecularColor"),
                uShininess: get(scene, "uShininess"),
            };
            p::Program::from_linked(gl, program).upload(gl, &u);
        };
        same_as_render(
            "phong-positional",
            upload,
            scenes::phong_positional::ATTRIBUTES,
        );
    }

    /// The uniforms of `spot.vert` and the lighting every spot fragment shader shares.
    macro_rules! spot_uniforms {
        ($p:ident, $scene:expr, { $($extra:ident: $value:expr),* $(,)? }) => {
            $p::Uniforms {
                u_worldViewProjection: get($scene, "u_worldViewProjection"),
                u_world: get($scene, "u_world"),
                u_worldInverseTranspose: get($scene, "u_worldInverseTranspose"),
                u_lightWorldPosition: get($scene, "u_lightWorldPosition"),
                u_viewWorldPosition: get($scene, "u_viewWorldPosition"),
                u_color: get($scene, "u_color"),
                u_shininess: get($scene, "u_shininess"),
                u_lightColor: get($scene, "u_lightColor"),
                u_specularColor: get($scene, "u_specularColor"),
                u_lightDirection: get($scene, "u_lightDirection"),
                $($extra: $value,)*
            }
        };
    }

    #[test]
    fn spot_lights() {
        let smooth = |gl: &mut essl_gl::Context, program, scene: &Scene| {
            use scenes::spot_smooth as p;
            let u = spot_uniforms!(p, scene, {
                u_innerLimit: get(scene, "u_innerLimit"),
                u_outerLimit: get(scene, "u_outerLimit"),
            });
            p::Program::from_linked(gl, program).upload(gl, &u);
        };
        same_as_render("spot-smooth", smooth, scenes::spot_smooth::ATTRIBUTES);
        let linear = |gl: &mut essl_gl::Context, program, scene: &Scene| {
            use scenes::spot_linear as p;
            let u = spot_uniforms!(p, scene, {
                u_innerLimit: get(scene, "u_innerLimit"),
                u_outerLimit: get(scene, "u_outerLimit"),
            });
            p::Program::from_linked(gl, program).upload(gl, &u);
        };
        same_as_render("spot-linear", linear, scenes::spot_linear::ATTRIBUTES);
        let hard = |gl: &mut essl_gl::Context, program, scene: &Scene| {
            use scenes::spot_hard as p;
            let u = spot_uniforms!(p, scene, { u_limit: get(scene, "u_limit") });
            p::Program::from_linked(gl, program).upload(gl, &u);
        };
        same_as_render("spot-hard", hard, scenes::spot_hard::ATTRIBUTES);
        let cookie = |gl: &mut essl_gl::Context, program, scene: &Scene| {
            use scenes::spot_cookie as p;
            let u = spot_uniforms!(p, scene, {
                u_innerLimit: get(scene, "u_innerLimit"),
                u_outerLimit: get(scene, "u_outerLimit"),
                u_viewport: get(scene, "u_viewport"),
                u_cookie: unit(scene, "u_cookie"),
            });
            p::Program::from_linked(gl, program).upload(gl, &u);
        };
        same_as_render("spot-cookie", cookie, scenes::spot_cookie::ATTRIBUTES);
    }
}

/// Without the shared scenes the bindings above were not generated: skip, or fail under
/// `ESSL_REQUIRE_CORPORA=1`.
#[cfg(not(essl_scenes))]
#[test]
fn scenes_are_absent() {
    assert!(
        essl_testdata::scenes().is_none(),
        "the scenes appeared after the build: rebuild"
    );
}
