//! The fixed-function state's values, with GL's initial ones: [`RenderState`] (viewport,
//! scissor, clear values, depth, culling, blending, masks, the stencil test's
//! [`StencilState`], the generic vertex attributes) and [`PixelStore`] (`pixel_storei`), and
//! GL's comparison functions, which the depth and stencil tests and sampler comparison share.
//! The calls that set them are in [`super`] and [`super::stencil`].

use crate::gl;
use crate::vertex_array::GenericAttrib;

/// The fixed-function state of a context, with GL's initial values.
#[derive(Clone, Debug)]
pub(crate) struct RenderState {
    pub(crate) viewport: [i32; 4],
    pub(crate) scissor: [i32; 4],
    pub(crate) scissor_test: bool,
    /// `CLIP_DISTANCEi_WEBGL` switches: bit i.
    pub(crate) clip_distances: u8,
    /// `EXT_clip_control`: `[CLIP_ORIGIN_EXT, CLIP_DEPTH_MODE_EXT]`.
    pub(crate) clip_control: [u32; 2],
    pub(crate) clear_color: [f32; 4],
    pub(crate) clear_depth: f32,
    pub(crate) clear_stencil: i32,
    pub(crate) depth_test: bool,
    pub(crate) depth_func: u32,
    pub(crate) depth_mask: bool,
    pub(crate) depth_range: [f32; 2],
    pub(crate) cull_face: bool,
    pub(crate) cull_face_mode: u32,
    pub(crate) front_face: u32,
    /// Blending and the colour mask of each draw buffer.
    pub(crate) draw_buffers: [super::DrawBufferState; super::blend::DRAW_BUFFERS],
    pub(crate) blend_color: [f32; 4],
    pub(crate) polygon_offset_fill: bool,
    pub(crate) polygon_offset_factor: f32,
    pub(crate) polygon_offset_units: f32,
    /// `polygonOffsetClampEXT`'s clamp (0: none).
    pub(crate) polygon_offset_clamp: f32,
    /// `POLYGON_OFFSET_LINE_WEBGL`: polygon offset for triangles drawn as lines.
    pub(crate) polygon_offset_line: bool,
    /// `polygonModeWEBGL(FRONT_AND_BACK, LINE_WEBGL)`: triangles drawn as their edges.
    pub(crate) polygon_line: bool,
    /// `DEPTH_CLAMP_EXT`: depth clamped to the depth range instead of clipped.
    pub(crate) depth_clamp: bool,
    pub(crate) rasterizer_discard: bool,
    pub(crate) dither: bool,
    pub(crate) stencil_test: bool,
    pub(crate) stencil: StencilState,
    pub(crate) sample_alpha_to_coverage: bool,
    pub(crate) sample_coverage: bool,
    /// `sampleCoverage`'s value and invert flag.
    pub(crate) sample_coverage_value: (f32, bool),
    /// `hint(GENERATE_MIPMAP_HINT)` and `hint(FRAGMENT_SHADER_DERIVATIVE_HINT)`.
    pub(crate) hints: [u32; 2],
    pub(crate) line_width: f32,
    /// The current value of each vertex attribute (`vertexAttrib4f`…), read by a draw where
    /// the attribute's array is disabled.
    pub(crate) generic_attribs: Vec<GenericAttrib>,
}

impl RenderState {
    /// GL's initial state for a `width` × `height` framebuffer and `attribs` vertex
    /// attributes.
    pub(crate) fn new(width: u32, height: u32, attribs: u32) -> Self {
        RenderState {
            viewport: [0, 0, width as i32, height as i32],
            scissor: [0, 0, width as i32, height as i32],
            scissor_test: false,
            clip_distances: 0,
            clip_control: super::clip_control::DEFAULT_CLIP_CONTROL,
            clear_color: [0.0; 4],
            clear_depth: 1.0,
            clear_stencil: 0,
            depth_test: false,
            depth_func: gl::LESS,
            depth_mask: true,
            depth_range: [0.0, 1.0],
            cull_face: false,
            cull_face_mode: gl::BACK,
            front_face: gl::CCW,
            draw_buffers: Default::default(),
            blend_color: [0.0; 4],
            polygon_offset_fill: false,
            polygon_offset_factor: 0.0,
            polygon_offset_units: 0.0,
            polygon_offset_clamp: 0.0,
            polygon_offset_line: false,
            polygon_line: false,
            depth_clamp: false,
            rasterizer_discard: false,
            dither: true,
            stencil_test: false,
            stencil: Default::default(),
            sample_alpha_to_coverage: false,
            sample_coverage: false,
            sample_coverage_value: (1.0, false),
            hints: [gl::DONT_CARE; 2],
            line_width: 1.0,
            generic_attribs: vec![GenericAttrib::default(); attribs as usize],
        }
    }

    /// Draw buffer `i`'s blending and colour mask; GL's initial ones (no blending, every
    /// channel written) past the last draw buffer.
    pub(crate) fn draw_buffer(&self, i: usize) -> super::DrawBufferState {
        self.draw_buffers.get(i).copied().unwrap_or_default()
    }
}

/// Pixel storage parameters (`pixel_storei`).
#[derive(Clone, Copy, Debug)]
pub(crate) struct PixelStore {
    pub(crate) unpack_alignment: u32,
    pub(crate) pack_alignment: u32,
    pub(crate) unpack_row_length: u32,
    pub(crate) unpack_skip_rows: u32,
    pub(crate) unpack_skip_pixels: u32,
    pub(crate) unpack_image_height: u32,
    pub(crate) unpack_skip_images: u32,
    pub(crate) pack_row_length: u32,
    pub(crate) pack_skip_rows: u32,
    pub(crate) pack_skip_pixels: u32,
    pub(crate) unpack_flip_y: bool,
    pub(crate) unpack_premultiply_alpha: bool,
    pub(crate) unpack_colorspace_conversion: u32,
}

impl Default for PixelStore {
    fn default() -> Self {
        PixelStore {
            unpack_alignment: 4,
            pack_alignment: 4,
            unpack_row_length: 0,
            unpack_skip_rows: 0,
            unpack_skip_pixels: 0,
            unpack_image_height: 0,
            unpack_skip_images: 0,
            pack_row_length: 0,
            pack_skip_rows: 0,
            pack_skip_pixels: 0,
            unpack_flip_y: false,
            unpack_premultiply_alpha: false,
            unpack_colorspace_conversion: gl::BROWSER_DEFAULT_WEBGL,
        }
    }
}

/// Whether `func` is one of GL's eight comparison functions.
pub(crate) fn is_compare_func(func: u32) -> bool {
    (gl::NEVER..=gl::ALWAYS).contains(&func)
}

/// Front ([0]) and back ([1]) stencil state, with GL's initial values.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct StencilState {
    pub(crate) func: [u32; 2],
    pub(crate) reference: [i32; 2],
    pub(crate) value_mask: [u32; 2],
    pub(crate) fail: [u32; 2],
    pub(crate) depth_fail: [u32; 2],
    pub(crate) pass: [u32; 2],
    pub(crate) writemask: [u32; 2],
}

impl Default for StencilState {
    fn default() -> Self {
        StencilState {
            func: [gl::ALWAYS; 2],
            reference: [0; 2],
            value_mask: [u32::MAX; 2],
            fail: [gl::KEEP; 2],
            depth_fail: [gl::KEEP; 2],
            pass: [gl::KEEP; 2],
            writemask: [u32::MAX; 2],
        }
    }
}

fn stencil_op(op: u32) -> wgpu::StencilOperation {
    use wgpu::StencilOperation as S;
    match op {
        gl::ZERO => S::Zero,
        gl::REPLACE => S::Replace,
        gl::INCR => S::IncrementClamp,
        gl::DECR => S::DecrementClamp,
        gl::INVERT => S::Invert,
        gl::INCR_WRAP => S::IncrementWrap,
        gl::DECR_WRAP => S::DecrementWrap,
        _ => S::Keep,
    }
}

impl StencilState {
    /// wgpu's stencil state with the test on (`STENCIL_TEST`) or off (always passes, writes
    /// nothing), for a stencil buffer of 8 bits.
    pub(crate) fn wgpu(&self, enabled: bool) -> wgpu::StencilState {
        if !enabled {
            return wgpu::StencilState::default();
        }
        let face = |i: usize| wgpu::StencilFaceState {
            compare: compare_function(self.func[i]),
            fail_op: stencil_op(self.fail[i]),
            depth_fail_op: stencil_op(self.depth_fail[i]),
            pass_op: stencil_op(self.pass[i]),
        };
        wgpu::StencilState {
            front: face(0),
            back: face(1),
            read_mask: self.value_mask[0] & 0xFF,
            write_mask: self.writemask[0] & 0xFF,
        }
    }

    /// The reference value wgpu compares with: GL clamps it to the buffer's range.
    pub(crate) fn reference(&self) -> u32 {
        self.reference[0].clamp(0, 0xFF) as u32
    }

    /// Whether front and back state agree as WebGL requires at a draw with a stencil buffer
    /// of 8 bits (references after clamping, masks in their low 8 bits).
    pub(crate) fn faces_agree(&self) -> bool {
        let r = self.reference.map(|r| r.clamp(0, 0xFF));
        r[0] == r[1]
            && self.value_mask[0] & 0xFF == self.value_mask[1] & 0xFF
            && self.writemask[0] & 0xFF == self.writemask[1] & 0xFF
    }
}

/// wgpu's comparison function for a GL one.
pub(crate) fn compare_function(func: u32) -> wgpu::CompareFunction {
    match func {
        gl::NEVER => wgpu::CompareFunction::Never,
        gl::LESS => wgpu::CompareFunction::Less,
        gl::EQUAL => wgpu::CompareFunction::Equal,
        gl::LEQUAL => wgpu::CompareFunction::LessEqual,
        gl::GREATER => wgpu::CompareFunction::Greater,
        gl::NOTEQUAL => wgpu::CompareFunction::NotEqual,
        gl::GEQUAL => wgpu::CompareFunction::GreaterEqual,
        _ => wgpu::CompareFunction::Always,
    }
}
