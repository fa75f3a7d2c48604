//! The binding map is all a host needs: a program with every kind of loose uniform is
//! translated to WGSL, and drawn on plain wgpu (no essl-gl) with its uniform buffer, textures,
//! samplers and vertex attribute set up from the JSON binding map alone. The fragment shader
//! compares every uniform with the value the host meant to give it and draws green when all
//! arrive, red otherwise; a deliberately misplaced value shows the check can fail. Skips, with a
//! message, without a Vulkan adapter, unless `ESSL_REQUIRE_ADAPTER=1`.

use essl::source::SourceFile;
use essl::{CompileOptions, Stage};
use essl_gl::wgpu;
use essl_translate::bindings::{BindingMap, Place};
use essl_translate::Options;

const VERT: &str = "#version 300 es
in vec2 a_corner;
uniform float u_scale[3];
void main() {
    gl_Position = vec4(a_corner * u_scale[2], 0.0, 1.0);
}
";

const FRAG: &str = "#version 300 es
precision highp float;
struct Light { vec3 color; bool on; int count; float weights[2]; };
uniform float u_scale[3];
uniform vec2 u_offsets[2];
uniform mat3x2 u_skew;
uniform mat4 u_matrix;
uniform Light u_lights[2];
uniform ivec2 u_size;
uniform uint u_mask;
uniform bool u_flag;
uniform sampler2D u_tex[2];
out vec4 outColor;
bool near(float a, float b) { return abs(a - b) < 1e-5; }
void main() {
    bool ok = near(u_scale[0], 0.5) && near(u_scale[1], 1.5) && near(u_scale[2], 1.0);
    ok = ok && u_offsets[0] == vec2(1.0, 2.0) && u_offsets[1] == vec2(3.0, 4.0);
    ok = ok && u_skew[0] == vec2(1.0, 2.0) && u_skew[1] == vec2(3.0, 4.0)
            && u_skew[2] == vec2(5.0, 6.0);
    ok = ok && u_matrix[3] == vec4(13.0, 14.0, 15.0, 16.0) && u_matrix[1].y == 6.0;
    ok = ok && u_lights[1].color == vec3(0.25, 0.5, 0.75) && u_lights[1].on
            && !u_lights[0].on && u_lights[1].count == -3
            && u_lights[1].weights[1] == 8.0 && u_lights[0].weights[0] == 5.0;
    ok = ok && u_size == ivec2(-7, 9) && u_mask == 0xdeadbeefu && u_flag;
    ok = ok && texture(u_tex[0], vec2(0.5)).r > 0.9 && texture(u_tex[1], vec2(0.5)).b > 0.9;
    outColor = ok ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0);
}
";

/// The values the host means to give, by WebGL name, as 32-bit words per element.
fn value(name: &str) -> Vec<Vec<u32>> {
    let f = |v: &[f32]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    match name {
        "u_scale[0]" => vec![f(&[0.5]), f(&[1.5]), f(&[1.0])],
        "u_offsets[0]" => vec![f(&[1.0, 2.0]), f(&[3.0, 4.0])],
        "u_skew" => vec![f(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0])],
        "u_matrix" => vec![f(&(1..=16).map(|i| i as f32).collect::<Vec<_>>())],
        "u_lights[0].color" => vec![f(&[0.0, 0.0, 0.0])],
        "u_lights[1].color" => vec![f(&[0.25, 0.5, 0.75])],
        "u_lights[0].on" => vec![vec![0]],
        "u_lights[1].on" => vec![vec![1]],
        "u_lights[0].count" => vec![vec![0]],
        "u_lights[1].count" => vec![vec![(-3i32) as u32]],
        "u_lights[0].weights[0]" => vec![f(&[5.0]), f(&[6.0])],
        "u_lights[1].weights[0]" => vec![f(&[7.0]), f(&[8.0])],
        "u_size" => vec![vec![(-7i32) as u32, 9]],
        "u_mask" => vec![vec![0xdead_beef]],
        "u_flag" => vec![vec![1]],
        other => panic!("no value for {other}"),
    }
}

/// Rows of a WebGL type: a matrix's columns are `rows` words, 16 bytes apart.
fn rows(ty: &str) -> Option<usize> {
    let rest = ty.strip_prefix("FLOAT_MAT")?;
    Some(match rest.split_once('x') {
        Some((_, r)) => r.parse().ok()?,
        None => rest.parse().ok()?,
    })
}

/// The uniform buffer's bytes, filled from the map; `misplace` writes one value 4 bytes off.
fn uniform_bytes(map: &BindingMap, height: f32, misplace: Option<&str>) -> Vec<u8> {
    let buffer = map.uniform_buffer.as_ref().expect("loose uniforms");
    let mut bytes = vec![0u8; buffer.size as usize];
    let mut put = |at: u32, word: u32| {
        bytes[at as usize..at as usize + 4].copy_from_slice(&word.to_le_bytes());
    };
    for u in &map.uniforms {
        let Place::Buffer {
            offset,
            array_stride,
            matrix_stride,
            ..
        } = u.place
        else {
            continue;
        };
        let shift = if misplace == Some(u.name.as_str()) {
            4
        } else {
            0
        };
        for (i, words) in value(&u.name).iter().enumerate() {
            let base = offset + i as u32 * array_stride + shift;
            match rows(&u.ty) {
                Some(r) => {
                    for (k, w) in words.iter().enumerate() {
                        let (col, row) = (k / r, k % r);
                        put(base + col as u32 * matrix_stride + row as u32 * 4, *w);
                    }
                }
                None => {
                    for (k, w) in words.iter().enumerate() {
                        put(base + k as u32 * 4, *w);
                    }
                }
            }
        }
    }
    for i in &map.internal {
        assert_eq!(i.value, "framebuffer_height");
        put(i.offset, height.to_bits());
    }
    bytes
}

/// Draws the program from its WGSL and the map; the centre pixel's RGBA.
fn draw(wgsl: [&str; 2], map: &BindingMap, misplace: Option<&str>) -> Option<[u8; 4]> {
    const SIZE: u32 = 16;
    let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
    desc.backends = wgpu::Backends::VULKAN;
    let instance = wgpu::Instance::new(desc);
    let adapter = essl_testdata::with_adapter(|| {
        pollster::block_on(instance.request_adapter(&Default::default()))
    })?;
    let (device, queue) =
        pollster::block_on(adapter.request_device(&Default::default())).expect("a device");
    let module = |text: &str, stage| {
        let (m, _) = essl_translate::roundtrip::read_wgsl(text, stage).expect("WGSL reads");
        device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: None,
            source: wgpu::ShaderSource::Naga(std::borrow::Cow::Owned(m)),
        })
    };
    let vs = module(wgsl[0], Stage::Vertex);
    let fs = module(wgsl[1], Stage::Fragment);

    // Group 0: the loose uniforms. Group 1: the texture and sampler of each sampler element.
    let ub = map.uniform_buffer.as_ref().expect("loose uniforms");
    assert_eq!((ub.group, ub.binding), (0, 0));
    let bytes = uniform_bytes(map, SIZE as f32, misplace);
    let buffer = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: bytes.len() as u64,
        usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    queue.write_buffer(&buffer, 0, &bytes);
    let all = wgpu::ShaderStages::VERTEX_FRAGMENT;
    let layout0 = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: None,
        entries: &[wgpu::BindGroupLayoutEntry {
            binding: ub.binding,
            visibility: all,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        }],
    });
    let group0 = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &layout0,
        entries: &[wgpu::BindGroupEntry {
            binding: ub.binding,
            resource: buffer.as_entire_binding(),
        }],
    });
    let sampler = device.create_sampler(&Default::default());
    let mut entries = Vec::new();
    let mut views = Vec::new();
    let colours = [[255u8, 0, 0, 255], [0, 0, 255, 255]];
    for u in &map.uniforms {
        let Place::Sampler {
            group,
            textures,
            samplers,
            ..
        } = &u.place
        else {
            continue;
        };
        assert_eq!(*group, 1);
        for (i, (&t, &s)) in textures.iter().zip(samplers).enumerate() {
            let texture = device.create_texture(&wgpu::TextureDescriptor {
                label: None,
                size: wgpu::Extent3d {
                    width: 1,
                    height: 1,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: wgpu::TextureFormat::Rgba8Unorm,
                usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
                view_formats: &[],
            });
            queue.write_texture(
                texture.as_image_copy(),
                &colours[i],
                wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(4),
                    rows_per_image: Some(1),
                },
                wgpu::Extent3d {
                    width: 1,
                    height: 1,
                    depth_or_array_layers: 1,
                },
            );
            views.push((t, s, texture.create_view(&Default::default())));
        }
    }
    for (t, s, _) in &views {
        entries.push(wgpu::BindGroupLayoutEntry {
            binding: *t,
            visibility: all,
            ty: wgpu::BindingType::Texture {
                sample_type: wgpu::TextureSampleType::Float { filterable: true },
                view_dimension: wgpu::TextureViewDimension::D2,
                multisampled: false,
            },
            count: None,
        });
        entries.push(wgpu::BindGroupLayoutEntry {
            binding: *s,
            visibility: all,
            ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
            count: None,
        });
    }
    let layout1 = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: None,
        entries: &entries,
    });
    let resources: Vec<wgpu::BindGroupEntry> = views
        .iter()
        .flat_map(|(t, s, view)| {
            [
                wgpu::BindGroupEntry {
                    binding: *t,
                    resource: wgpu::BindingResource::TextureView(view),
                },
                wgpu::BindGroupEntry {
                    binding: *s,
                    resource: wgpu::BindingResource::Sampler(&sampler),
                },
            ]
        })
        .collect();
    let group1 = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &layout1,
        entries: &resources,
    });

    // The attribute at the map's location: two triangles over the viewport.
    let corner = map
        .attributes
        .iter()
        .find(|a| a.name == "a_corner")
        .expect("a_corner in the map");
    let quad: [f32; 12] = [
        -1.0, -1.0, 1.0, -1.0, -1.0, 1.0, -1.0, 1.0, 1.0, -1.0, 1.0, 1.0,
    ];
    let vertices = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: 48,
        usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let quad_bytes: Vec<u8> = quad.iter().flat_map(|x| x.to_le_bytes()).collect();
    queue.write_buffer(&vertices, 0, &quad_bytes);
    let attributes = [wgpu::VertexAttribute {
        format: wgpu::VertexFormat::Float32x2,
        offset: 0,
        shader_location: corner.location,
    }];
    let output = map.outputs.first().expect("an output").location;
    let format = wgpu::TextureFormat::Rgba8Unorm;
    let mut targets = vec![None; output as usize + 1];
    targets[output as usize] = Some(wgpu::ColorTargetState {
        format,
        blend: None,
        write_mask: wgpu::ColorWrites::ALL,
    });
    let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: None,
        bind_group_layouts: &[Some(&layout0), Some(&layout1)],
        immediate_size: 0,
    });
    let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: None,
        layout: Some(&pipeline_layout),
        vertex: wgpu::VertexState {
            module: &vs,
            entry_point: Some("main"),
            compilation_options: Default::default(),
            buffers: &[Some(wgpu::VertexBufferLayout {
                array_stride: 8,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &attributes,
            })],
        },
        primitive: Default::default(),
        depth_stencil: None,
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module: &fs,
            entry_point: Some("main"),
            compilation_options: Default::default(),
            targets: &targets,
        }),
        multiview_mask: None,
        cache: None,
    });
    let target = device.create_texture(&wgpu::TextureDescriptor {
        label: None,
        size: wgpu::Extent3d {
            width: SIZE,
            height: SIZE,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    });
    let view = target.create_view(&Default::default());
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: 256 * SIZE as u64,
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut attachments = vec![None; output as usize + 1];
        attachments[output as usize] = Some(wgpu::RenderPassColorAttachment {
            view: &view,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations {
                load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                store: wgpu::StoreOp::Store,
            },
        });
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: None,
            color_attachments: &attachments,
            depth_stencil_attachment: None,
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &group0, &[]);
        pass.set_bind_group(1, &group1, &[]);
        pass.set_vertex_buffer(0, vertices.slice(..));
        pass.draw(0..6, 0..1);
    }
    encoder.copy_texture_to_buffer(
        target.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &readback,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(256),
                rows_per_image: Some(SIZE),
            },
        },
        wgpu::Extent3d {
            width: SIZE,
            height: SIZE,
            depth_or_array_layers: 1,
        },
    );
    queue.submit([encoder.finish()]);
    let slice = readback.slice(..);
    slice.map_async(wgpu::MapMode::Read, |r| r.expect("the readback maps"));
    device
        .poll(wgpu::PollType::wait_indefinitely())
        .expect("the GPU finishes");
    let data = slice.get_mapped_range().expect("the readback is mapped");
    let at = (SIZE as usize / 2) * 256 + (SIZE as usize / 2) * 4;
    Some([data[at], data[at + 1], data[at + 2], data[at + 3]])
}

#[test]
fn the_binding_map_alone_feeds_the_wgsl() {
    let compile = |text: &str, stage| {
        essl::compile(
            SourceFile::new("every-uniform", text.to_owned()),
            stage,
            &CompileOptions::default(),
        )
    };
    let (vs, fs) = (compile(VERT, Stage::Vertex), compile(FRAG, Stage::Fragment));
    assert!(
        vs.ok() && fs.ok(),
        "{:?}{:?}",
        vs.diagnostics,
        fs.diagnostics
    );
    let t = essl_translate::translate_program(&vs, &fs, &Options::default()).expect("translates");
    // Through JSON, as a host in another language would read it.
    let map: BindingMap = serde_json::from_str(&t.bindings.to_json()).expect("the map reads");
    assert_eq!(map, t.bindings);
    let wgsl = [
        t.vertex.as_text().expect("text"),
        t.fragment.as_text().expect("text"),
    ];
    let Some(pixel) = draw(wgsl, &map, None) else {
        return;
    };
    assert_eq!(pixel, [0, 255, 0, 255], "every uniform arrives");
    for wrong in ["u_lights[1].weights[0]", "u_skew", "u_offsets[0]"] {
        let pixel = draw(wgsl, &map, Some(wrong)).expect("an adapter, as before");
        assert_eq!(pixel, [255, 0, 0, 255], "{wrong} 4 bytes off must show");
    }
}
