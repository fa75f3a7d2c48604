"""The probe scripts of tests/gl-scripts/probes/: a few calls each, asking Chromium's WebGL2 what it
answers (`record`) and which GL error it sets (`error`) for the framebuffer, renderbuffer, blit,
readPixels, clearBuffer, stencil, sampler, query, sync and transform feedback API.

Written by make_scripts.py. A probe's `error` fields are what Chromium answered, checked against the
WebGL 2.0 and OpenGL ES 3.0 specifications; where the two differ the doc (docs/gl-scripts.md) says so.
"""
import os

from make_scripts import F32, I32, OR, OUT, R, U16, U32, Script

PROBES = []
FULLSCREEN = "common-fullscreen.vert"


def probe(name, description, width=16, height=16, **kw):
    def register(fn):
        PROBES.append((name, description, fn, width, height, kw))
        return fn
    return register


def program(s, name, frag, vert=FULLSCREEN, uniforms=(), **kw):
    s.program(name, vert, frag, uniforms, **kw)


def solid(s, name="solid", color=(0.2, 0.6, 1.0, 1.0)):
    """A program that fills the viewport with one colour (drawArrays(TRIANGLES, 0, 3))."""
    program(s, name, "common-solid.frag", uniforms=["u_color"])
    s("useProgram", R(name))
    s("uniform4fv", R(f"{name}.u_color"), F32(color))


def draw(s, error=None):
    s("drawArrays", "TRIANGLES", 0, 3, error=error)


def color_fb(s, name, internal="RGBA8", size=4, point="COLOR_ATTACHMENT0"):
    """A framebuffer with one size x size texture of this format; its status recorded."""
    s.texture(name + "Tex", "TEXTURE_2D", internal, size, size)
    s.framebuffer(name, [(point, name + "Tex", "TEXTURE_2D")])


def read(s, key, x=0, y=0, fmt="RGBA", kind="UNSIGNED_BYTE", out="u8", error=None):
    s("readPixels", x, y, 1, 1, fmt, kind, OUT(out, 4), record=key, error=error)


# ---------------------------------------------------------------- framebuffer completeness

@probe("fb-status-color-formats", "checkFramebufferStatus with one 4x4 colour texture of each format: the "
       "colour-renderable sized formats of ES 3.0 are complete; without EXT_color_buffer_float the float and "
       "half-float formats are not (INCOMPLETE_ATTACHMENT), nor are RGB9_E5, SRGB8, RGBA8_SNORM and the "
       "unsized LUMINANCE.")
def fb_status_color_formats(s):
    for internal in ("RGBA8", "RGB8", "RG8", "R8", "RGB565", "RGBA4", "RGB5_A1", "RGB10_A2", "SRGB8_ALPHA8",
                     "RGBA8UI", "RGBA8I", "R32UI", "RG16I", "RGBA32I", "RGB10_A2UI",
                     "RGBA16F", "RGBA32F", "R16F", "R11F_G11F_B10F", "RGB9_E5", "SRGB8", "RGBA8_SNORM"):
        color_fb(s, internal.lower(), internal)
    s("createTexture", as_="luminanceTex")
    s("bindTexture", "TEXTURE_2D", R("luminanceTex"))
    s("texImage2D", "TEXTURE_2D", 0, "LUMINANCE", 4, 4, 0, "LUMINANCE", "UNSIGNED_BYTE", None)
    s.framebuffer("luminance", [("COLOR_ATTACHMENT0", "luminanceTex", "TEXTURE_2D")])


@probe("fb-status-float-extension", "With EXT_color_buffer_float enabled, the float and half-float colour "
       "formats become complete (RGBA16F, RGBA32F, R16F, RG32F, R11F_G11F_B10F); RGB16F, RGB32F and RGB9_E5 "
       "stay INCOMPLETE_ATTACHMENT.", extensions=["EXT_color_buffer_float"])
def fb_status_float_extension(s):
    for internal in ("RGBA16F", "RGBA32F", "R16F", "RG32F", "R11F_G11F_B10F", "RGB16F", "RGB32F", "RGB9_E5"):
        color_fb(s, internal.lower(), internal)


@probe("fb-status-missing-attachment", "A framebuffer with nothing attached is "
       "FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT; clear, drawArrays, readPixels and blitFramebuffer with it "
       "bound give INVALID_FRAMEBUFFER_OPERATION and leave the canvas as cleared.")
def fb_status_missing_attachment(s):
    solid(s)
    s("clearColor", 0.0, 0.5, 0.0, 1.0)
    s("clear", "COLOR_BUFFER_BIT")
    s("createFramebuffer", as_="empty")
    s("bindFramebuffer", "FRAMEBUFFER", R("empty"))
    s("checkFramebufferStatus", "FRAMEBUFFER", record="empty.status")
    s("checkFramebufferStatus", "READ_FRAMEBUFFER", record="empty.readStatus")
    s("clear", "COLOR_BUFFER_BIT", error="INVALID_FRAMEBUFFER_OPERATION")
    draw(s, error="INVALID_FRAMEBUFFER_OPERATION")
    s("readPixels", 0, 0, 1, 1, "RGBA", "UNSIGNED_BYTE", OUT("u8", 4), error="INVALID_FRAMEBUFFER_OPERATION")
    s("bindFramebuffer", "DRAW_FRAMEBUFFER", None)
    s("blitFramebuffer", 0, 0, 4, 4, 0, 0, 4, 4, "COLOR_BUFFER_BIT", "NEAREST", error="INVALID_FRAMEBUFFER_OPERATION")
    s("bindFramebuffer", "FRAMEBUFFER", None)
    s("checkFramebufferStatus", "FRAMEBUFFER", record="default.status")


@probe("fb-status-dimensions", "Attachments of different sizes: WebGL 2 keeps WebGL 1's rule, "
       "FRAMEBUFFER_INCOMPLETE_DIMENSIONS (ES 3.0 would allow it), for two colour textures and for colour + "
       "depth renderbuffer.")
def fb_status_dimensions(s):
    s.texture("a", "TEXTURE_2D", "RGBA8", 8, 8)
    s.texture("b", "TEXTURE_2D", "RGBA8", 4, 4)
    s.renderbuffer("depth", "DEPTH_COMPONENT16", 4, 4)
    s.framebuffer("twoColors", [("COLOR_ATTACHMENT0", "a", "TEXTURE_2D"), ("COLOR_ATTACHMENT1", "b", "TEXTURE_2D")])
    s.framebuffer("colorDepth", [("COLOR_ATTACHMENT0", "a", "TEXTURE_2D"),
                                 ("DEPTH_ATTACHMENT", "depth", "renderbuffer")])
    s("clear", "COLOR_BUFFER_BIT", error="INVALID_FRAMEBUFFER_OPERATION")
    s.framebuffer("sameSize", [("COLOR_ATTACHMENT0", "b", "TEXTURE_2D"), ("DEPTH_ATTACHMENT", "depth", "renderbuffer")])
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("fb-status-depth-stencil", "Depth and stencil combinations: DEPTH24_STENCIL8 at "
       "DEPTH_STENCIL_ATTACHMENT, or the same image at DEPTH_ATTACHMENT and STENCIL_ATTACHMENT, is complete; "
       "different images at the two points are FRAMEBUFFER_UNSUPPORTED; a depth-only format at "
       "DEPTH_STENCIL_ATTACHMENT or STENCIL_INDEX8 at DEPTH_ATTACHMENT is INCOMPLETE_ATTACHMENT.")
def fb_status_depth_stencil(s):
    s.texture("color", "TEXTURE_2D", "RGBA8", 4, 4)
    for name, internal in (("d16", "DEPTH_COMPONENT16"), ("d24s8", "DEPTH24_STENCIL8"), ("s8", "STENCIL_INDEX8"),
                           ("d32fs8", "DEPTH32F_STENCIL8")):
        s.renderbuffer(name, internal, 4, 4)
    c = ("COLOR_ATTACHMENT0", "color", "TEXTURE_2D")
    s.framebuffer("depthStencilPoint", [c, ("DEPTH_STENCIL_ATTACHMENT", "d24s8", "renderbuffer")])
    s.framebuffer("sameImageTwoPoints", [c, ("DEPTH_ATTACHMENT", "d24s8", "renderbuffer"),
                                         ("STENCIL_ATTACHMENT", "d24s8", "renderbuffer")])
    s.framebuffer("differentImages", [c, ("DEPTH_ATTACHMENT", "d16", "renderbuffer"),
                                      ("STENCIL_ATTACHMENT", "s8", "renderbuffer")])
    s.framebuffer("depthOnlyAtDepthStencil", [c, ("DEPTH_STENCIL_ATTACHMENT", "d16", "renderbuffer")])
    s.framebuffer("stencilAtDepth", [c, ("DEPTH_ATTACHMENT", "s8", "renderbuffer")])
    s.framebuffer("stencilOnly", [c, ("STENCIL_ATTACHMENT", "s8", "renderbuffer")])
    s.framebuffer("depthStencilAtDepth", [c, ("DEPTH_ATTACHMENT", "d24s8", "renderbuffer")])
    s.framebuffer("float32DepthStencil", [c, ("DEPTH_STENCIL_ATTACHMENT", "d32fs8", "renderbuffer")])
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("fb-depth-stencil-alias", "WebGL 2's DEPTH_STENCIL_ATTACHMENT sets both points: depth renderbuffer at "
       "DEPTH_ATTACHMENT, a DEPTH24_STENCIL8 at DEPTH_STENCIL_ATTACHMENT, then null at DEPTH_STENCIL_ATTACHMENT "
       "leaves neither attached; querying DEPTH_STENCIL_ATTACHMENT while depth and stencil differ is "
       "INVALID_OPERATION.")
def fb_depth_stencil_alias(s):
    s.renderbuffer("d16", "DEPTH_COMPONENT16", 4, 4)
    s.renderbuffer("d24s8", "DEPTH24_STENCIL8", 4, 4)
    s.renderbuffer("s8", "STENCIL_INDEX8", 4, 4)
    s("createFramebuffer", as_="fb")
    s("bindFramebuffer", "FRAMEBUFFER", R("fb"))
    s("framebufferRenderbuffer", "FRAMEBUFFER", "DEPTH_ATTACHMENT", "RENDERBUFFER", R("d16"))
    s("framebufferRenderbuffer", "FRAMEBUFFER", "DEPTH_STENCIL_ATTACHMENT", "RENDERBUFFER", R("d24s8"))
    for point in ("DEPTH_ATTACHMENT", "STENCIL_ATTACHMENT", "DEPTH_STENCIL_ATTACHMENT"):
        s("getFramebufferAttachmentParameter", "FRAMEBUFFER", point, "FRAMEBUFFER_ATTACHMENT_OBJECT_NAME",
          record=f"afterDepthStencil.{point}")
    s("framebufferRenderbuffer", "FRAMEBUFFER", "DEPTH_STENCIL_ATTACHMENT", "RENDERBUFFER", None)
    for point in ("DEPTH_ATTACHMENT", "STENCIL_ATTACHMENT"):
        s("getFramebufferAttachmentParameter", "FRAMEBUFFER", point, "FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE",
          record=f"afterNull.{point}")
    s("framebufferRenderbuffer", "FRAMEBUFFER", "DEPTH_ATTACHMENT", "RENDERBUFFER", R("d16"))
    s("framebufferRenderbuffer", "FRAMEBUFFER", "STENCIL_ATTACHMENT", "RENDERBUFFER", R("s8"))
    s("getFramebufferAttachmentParameter", "FRAMEBUFFER", "DEPTH_STENCIL_ATTACHMENT",
      "FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE", error="INVALID_OPERATION", record="differing.depthStencilQuery")
    s("checkFramebufferStatus", "FRAMEBUFFER", record="differing.status")
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("fb-same-image-twice", "One texture image at COLOR_ATTACHMENT0 and COLOR_ATTACHMENT1 is "
       "FRAMEBUFFER_UNSUPPORTED in WebGL 2; two layers of one 2D array texture are complete; two levels of one "
       "texture differ in size, so INCOMPLETE_DIMENSIONS.")
def fb_same_image_twice(s):
    s.texture("tex", "TEXTURE_2D", "RGBA8", 8, 8, levels=2)
    s.framebuffer("twice", [("COLOR_ATTACHMENT0", "tex", "TEXTURE_2D"), ("COLOR_ATTACHMENT1", "tex", "TEXTURE_2D")])
    s("createTexture", as_="array")
    s("bindTexture", "TEXTURE_2D_ARRAY", R("array"))
    s("texStorage3D", "TEXTURE_2D_ARRAY", 1, "RGBA8", 4, 4, 2)
    s("createFramebuffer", as_="twoLayers")
    s("bindFramebuffer", "FRAMEBUFFER", R("twoLayers"))
    s("framebufferTextureLayer", "FRAMEBUFFER", "COLOR_ATTACHMENT0", R("array"), 0, 0)
    s("framebufferTextureLayer", "FRAMEBUFFER", "COLOR_ATTACHMENT1", R("array"), 0, 1)
    s("checkFramebufferStatus", "FRAMEBUFFER", record="twoLayers.status")
    s("createFramebuffer", as_="twoLevels")
    s("bindFramebuffer", "FRAMEBUFFER", R("twoLevels"))
    s("framebufferTexture2D", "FRAMEBUFFER", "COLOR_ATTACHMENT0", "TEXTURE_2D", R("tex"), 0)
    s("framebufferTexture2D", "FRAMEBUFFER", "COLOR_ATTACHMENT1", "TEXTURE_2D", R("tex"), 1)
    s("checkFramebufferStatus", "FRAMEBUFFER", record="twoLevels.status")
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("fb-attach-errors", "framebufferTexture2D errors: the cube map target itself (INVALID_ENUM), a cube face "
       "with a 2D texture (INVALID_OPERATION), a level beyond log2(MAX_TEXTURE_SIZE) (INVALID_VALUE), "
       "COLOR_ATTACHMENT beyond MAX_COLOR_ATTACHMENTS (INVALID_ENUM), nothing bound (INVALID_OPERATION); "
       "framebufferTextureLayer on a 2D array layer is complete, a layer past the array's depth is accepted but "
       "leaves the framebuffer incomplete, one past MAX_ARRAY_TEXTURE_LAYERS is INVALID_VALUE, a 2D texture "
       "INVALID_OPERATION.")
def fb_attach_errors(s):
    s.texture("tex2d", "TEXTURE_2D", "RGBA8", 4, 4)
    s.texture("cube", "TEXTURE_CUBE_MAP", "RGBA8", 4, 4)
    s("framebufferTexture2D", "FRAMEBUFFER", "COLOR_ATTACHMENT0", "TEXTURE_2D", R("tex2d"), 0,
      error="INVALID_OPERATION")
    s("createFramebuffer", as_="fb")
    s("bindFramebuffer", "FRAMEBUFFER", R("fb"))
    s("framebufferTexture2D", "FRAMEBUFFER", "COLOR_ATTACHMENT0", "TEXTURE_CUBE_MAP", R("cube"), 0,
      error="INVALID_ENUM")
    s("framebufferTexture2D", "FRAMEBUFFER", "COLOR_ATTACHMENT0", "TEXTURE_CUBE_MAP_POSITIVE_X", R("tex2d"), 0,
      error="INVALID_OPERATION")
    s("framebufferTexture2D", "FRAMEBUFFER", "COLOR_ATTACHMENT0", "TEXTURE_2D", R("cube"), 0,
      error="INVALID_OPERATION")
    s("framebufferTexture2D", "FRAMEBUFFER", "COLOR_ATTACHMENT0", "TEXTURE_2D", R("tex2d"), 20, error="INVALID_VALUE")
    s("framebufferTexture2D", "FRAMEBUFFER", "COLOR_ATTACHMENT15", "TEXTURE_2D", R("tex2d"), 0,
      error="INVALID_ENUM")
    s("framebufferTexture2D", "FRAMEBUFFER", "COLOR_ATTACHMENT0", "TEXTURE_CUBE_MAP_NEGATIVE_Z", R("cube"), 0)
    s("checkFramebufferStatus", "FRAMEBUFFER", record="cubeFace.status")
    s("createTexture", as_="array")
    s("bindTexture", "TEXTURE_2D_ARRAY", R("array"))
    s("texStorage3D", "TEXTURE_2D_ARRAY", 1, "RGBA8", 4, 4, 3)
    s("framebufferTextureLayer", "FRAMEBUFFER", "COLOR_ATTACHMENT0", R("array"), 0, 2)
    s("checkFramebufferStatus", "FRAMEBUFFER", record="arrayLayer.status")
    s("getFramebufferAttachmentParameter", "FRAMEBUFFER", "COLOR_ATTACHMENT0",
      "FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER", record="arrayLayer.layer")
    s("framebufferTextureLayer", "FRAMEBUFFER", "COLOR_ATTACHMENT0", R("array"), 0, 3)
    s("checkFramebufferStatus", "FRAMEBUFFER", record="layerPastDepth.status")
    s("framebufferTextureLayer", "FRAMEBUFFER", "COLOR_ATTACHMENT0", R("array"), 0, 100000, error="INVALID_VALUE")
    s("framebufferTextureLayer", "FRAMEBUFFER", "COLOR_ATTACHMENT0", R("tex2d"), 0, 0, error="INVALID_OPERATION")
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("fb-attachment-parameters", "getFramebufferAttachmentParameter on an RGBA8 texture attachment, an empty "
       "attachment point (OBJECT_TYPE NONE and OBJECT_NAME null without error, anything else "
       "INVALID_OPERATION), a DEPTH24_STENCIL8 renderbuffer (COMPONENT_TYPE of DEPTH_STENCIL_ATTACHMENT "
       "is INVALID_OPERATION) and the default framebuffer (BACK, DEPTH, STENCIL).",
       context={"stencil": True})
def fb_attachment_parameters(s):
    s.texture("tex", "TEXTURE_2D", "RGBA8", 4, 4, levels=2)
    s.renderbuffer("d24s8", "DEPTH24_STENCIL8", 4, 4)
    s("createFramebuffer", as_="fb")
    s("bindFramebuffer", "FRAMEBUFFER", R("fb"))
    s("framebufferTexture2D", "FRAMEBUFFER", "COLOR_ATTACHMENT0", "TEXTURE_2D", R("tex"), 0)
    s("framebufferRenderbuffer", "FRAMEBUFFER", "DEPTH_STENCIL_ATTACHMENT", "RENDERBUFFER", R("d24s8"))
    for p in ("OBJECT_TYPE", "OBJECT_NAME", "TEXTURE_LEVEL", "TEXTURE_CUBE_MAP_FACE", "TEXTURE_LAYER", "RED_SIZE",
              "GREEN_SIZE", "BLUE_SIZE", "ALPHA_SIZE", "DEPTH_SIZE", "STENCIL_SIZE", "COMPONENT_TYPE",
              "COLOR_ENCODING"):
        s("getFramebufferAttachmentParameter", "FRAMEBUFFER", "COLOR_ATTACHMENT0", f"FRAMEBUFFER_ATTACHMENT_{p}",
          record=f"color0.{p}")
    for p in ("OBJECT_TYPE", "OBJECT_NAME"):
        s("getFramebufferAttachmentParameter", "FRAMEBUFFER", "COLOR_ATTACHMENT1", f"FRAMEBUFFER_ATTACHMENT_{p}",
          record=f"color1.{p}")
    s("getFramebufferAttachmentParameter", "FRAMEBUFFER", "COLOR_ATTACHMENT1", "FRAMEBUFFER_ATTACHMENT_RED_SIZE",
      error="INVALID_OPERATION", record="color1.RED_SIZE")
    for point in ("DEPTH_ATTACHMENT", "STENCIL_ATTACHMENT", "DEPTH_STENCIL_ATTACHMENT"):
        for p in ("OBJECT_TYPE", "DEPTH_SIZE", "STENCIL_SIZE", "COMPONENT_TYPE"):
            bad = point == "DEPTH_STENCIL_ATTACHMENT" and p == "COMPONENT_TYPE"
            s("getFramebufferAttachmentParameter", "FRAMEBUFFER", point, f"FRAMEBUFFER_ATTACHMENT_{p}",
              record=f"{point}.{p}", error="INVALID_OPERATION" if bad else None)
    s("getFramebufferAttachmentParameter", "FRAMEBUFFER", "BACK", "FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE",
      error="INVALID_ENUM", record="fbo.BACK")
    s("bindFramebuffer", "FRAMEBUFFER", None)
    for point in ("BACK", "DEPTH", "STENCIL"):
        for p in ("OBJECT_TYPE", "RED_SIZE", "ALPHA_SIZE", "DEPTH_SIZE", "STENCIL_SIZE", "COMPONENT_TYPE",
                  "COLOR_ENCODING"):
            s("getFramebufferAttachmentParameter", "FRAMEBUFFER", point, f"FRAMEBUFFER_ATTACHMENT_{p}",
              record=f"default.{point}.{p}")
    s("getFramebufferAttachmentParameter", "FRAMEBUFFER", "COLOR_ATTACHMENT0", "FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE",
      error="INVALID_ENUM", record="default.COLOR_ATTACHMENT0")


# ---------------------------------------------------------------- renderbuffers and samples

@probe("rb-parameters", "getRenderbufferParameter for RGBA8, RGB565, DEPTH_COMPONENT16, DEPTH24_STENCIL8, "
       "STENCIL_INDEX8 and a 4-sample RGBA8: WIDTH, HEIGHT, INTERNAL_FORMAT, SAMPLES and the bit sizes.")
def rb_parameters(s):
    for name, internal, samples in (("rgba8", "RGBA8", 0), ("rgb565", "RGB565", 0), ("d16", "DEPTH_COMPONENT16", 0),
                                    ("d24s8", "DEPTH24_STENCIL8", 0), ("s8", "STENCIL_INDEX8", 0),
                                    ("rgba8ms", "RGBA8", 4)):
        s.renderbuffer(name, internal, 6, 5, samples=samples)
        for p in ("WIDTH", "HEIGHT", "INTERNAL_FORMAT", "SAMPLES", "RED_SIZE", "GREEN_SIZE", "BLUE_SIZE",
                  "ALPHA_SIZE", "DEPTH_SIZE", "STENCIL_SIZE"):
            s("getRenderbufferParameter", "RENDERBUFFER", f"RENDERBUFFER_{p}", record=f"{name}.{p}")


@probe("rb-storage-errors", "renderbufferStorage(Multisample) errors: nothing bound (INVALID_OPERATION), unsized "
       "RGBA (INVALID_ENUM) but DEPTH_STENCIL accepted as in WebGL 1, RGBA32F without EXT_color_buffer_float "
       "(INVALID_ENUM), a size over MAX_RENDERBUFFER_SIZE or negative (INVALID_VALUE), more samples than "
       "MAX_SAMPLES or samples for an integer format (INVALID_OPERATION).")
def rb_storage_errors(s):
    s("renderbufferStorage", "RENDERBUFFER", "RGBA8", 4, 4, error="INVALID_OPERATION")
    s("getRenderbufferParameter", "RENDERBUFFER", "RENDERBUFFER_WIDTH", error="INVALID_OPERATION",
      record="unbound.width")
    s("createRenderbuffer", as_="rb")
    s("bindRenderbuffer", "RENDERBUFFER", R("rb"))
    s("renderbufferStorage", "RENDERBUFFER", "RGBA", 4, 4, error="INVALID_ENUM")
    s("renderbufferStorage", "RENDERBUFFER", "DEPTH_STENCIL", 4, 4)
    s("getRenderbufferParameter", "RENDERBUFFER", "RENDERBUFFER_INTERNAL_FORMAT", record="depthStencil.format")
    s("renderbufferStorage", "RENDERBUFFER", "RGBA32F", 4, 4, error="INVALID_ENUM")
    s("getParameter", "MAX_RENDERBUFFER_SIZE", record="MAX_RENDERBUFFER_SIZE")
    s("renderbufferStorage", "RENDERBUFFER", "RGBA8", 100000, 4, error="INVALID_VALUE")
    s("renderbufferStorage", "RENDERBUFFER", "RGBA8", -1, 4, error="INVALID_VALUE")
    s("renderbufferStorageMultisample", "RENDERBUFFER", 64, "RGBA8", 4, 4, error="INVALID_OPERATION")
    s("renderbufferStorageMultisample", "RENDERBUFFER", 4, "R32UI", 4, 4, error="INVALID_OPERATION")
    s("renderbufferStorageMultisample", "RENDERBUFFER", -1, "RGBA8", 4, 4, error="INVALID_VALUE")
    s("renderbufferStorageMultisample", "RENDERBUFFER", 2, "RGBA8", 4, 4)
    s("getRenderbufferParameter", "RENDERBUFFER", "RENDERBUFFER_SAMPLES", record="askedFor2.samples")


@probe("rb-internalformat-samples", "getInternalformatParameter(RENDERBUFFER, format, SAMPLES) for colour, depth, "
       "stencil and integer formats (the sample counts this GPU offers, highest first; an empty list for the "
       "integer formats), and INVALID_ENUM for a texture target, an unrenderable format or another pname.")
def rb_internalformat_samples(s):
    for internal in ("RGBA8", "RGB565", "SRGB8_ALPHA8", "RGB10_A2", "DEPTH_COMPONENT16", "DEPTH24_STENCIL8",
                     "DEPTH32F_STENCIL8", "STENCIL_INDEX8", "R8UI", "RGBA32I"):
        s("getInternalformatParameter", "RENDERBUFFER", internal, "SAMPLES", record=f"{internal}.SAMPLES")
    s("getInternalformatParameter", "TEXTURE_2D", "RGBA8", "SAMPLES", error="INVALID_ENUM", record="texture2d")
    s("getInternalformatParameter", "RENDERBUFFER", "RGBA32F", "SAMPLES", error="INVALID_ENUM", record="RGBA32F")
    s("getInternalformatParameter", "RENDERBUFFER", "RGBA8", "RENDERBUFFER_WIDTH", error="INVALID_ENUM",
      record="otherPname")


@probe("rb-internalformat-samples-float", "getInternalformatParameter(SAMPLES) for the float formats once "
       "EXT_color_buffer_float is on.", extensions=["EXT_color_buffer_float"])
def rb_internalformat_samples_float(s):
    for internal in ("RGBA16F", "RGBA32F", "R32F", "R11F_G11F_B10F"):
        s("getInternalformatParameter", "RENDERBUFFER", internal, "SAMPLES", record=f"{internal}.SAMPLES")


@probe("fb-status-multisample", "Mixed sample counts: a 4-sample colour renderbuffer with a single-sample depth "
       "renderbuffer, or with a texture, is FRAMEBUFFER_INCOMPLETE_MULTISAMPLE; 4 + 4 samples is complete and "
       "getParameter(SAMPLES) says 4 while it is bound.")
def fb_status_multisample(s):
    s.renderbuffer("colorMs", "RGBA8", 4, 4, samples=4)
    s.renderbuffer("depthMs", "DEPTH_COMPONENT16", 4, 4, samples=4)
    s.renderbuffer("depth", "DEPTH_COMPONENT16", 4, 4)
    s.texture("tex", "TEXTURE_2D", "RGBA8", 4, 4)
    s.framebuffer("msDepthSingle", [("COLOR_ATTACHMENT0", "colorMs", "renderbuffer"),
                                    ("DEPTH_ATTACHMENT", "depth", "renderbuffer")])
    s.framebuffer("msAndTexture", [("COLOR_ATTACHMENT0", "colorMs", "renderbuffer"),
                                   ("COLOR_ATTACHMENT1", "tex", "TEXTURE_2D")])
    s.framebuffer("msBoth", [("COLOR_ATTACHMENT0", "colorMs", "renderbuffer"),
                             ("DEPTH_ATTACHMENT", "depthMs", "renderbuffer")])
    s("getParameter", "SAMPLES", record="msBoth.SAMPLES")
    s("getParameter", "SAMPLE_BUFFERS", record="msBoth.SAMPLE_BUFFERS")
    s("bindFramebuffer", "FRAMEBUFFER", None)
    s("getParameter", "SAMPLES", record="default.SAMPLES")


# ---------------------------------------------------------------- feedback loops

def feedback_setup(s, levels=1):
    program(s, "show", "probes/sample.frag", uniforms=["u_texture"])
    s("useProgram", R("show"))
    s("uniform1i", R("show.u_texture"), 0)
    s.texture("tex", "TEXTURE_2D", "RGBA8", 4, 4, levels=levels)
    s("texSubImage2D", "TEXTURE_2D", 0, 0, 0, 4, 4, "RGBA", "UNSIGNED_BYTE", {"u8": [10, 20, 30, 255] * 16})
    s.framebuffer("fb", [("COLOR_ATTACHMENT0", "tex", "TEXTURE_2D")])
    s("viewport", 0, 0, 4, 4)


@probe("feedback-loop-draw", "A feedback loop: the texture attached to the draw framebuffer is bound to the unit "
       "the program samples; drawArrays is INVALID_OPERATION and draws nothing (texel (0, 0) keeps its value); "
       "with the texture unbound from the unit the draw goes through (an empty unit reads (0, 0, 0, 1)).")
def feedback_loop_draw(s):
    feedback_setup(s)
    draw(s, error="INVALID_OPERATION")
    read(s, "texel00")
    s("bindTexture", "TEXTURE_2D", None)
    draw(s)
    read(s, "unboundThenDrawn.texel00")
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("feedback-loop-unused-unit", "No feedback loop when the attached texture is bound only to a unit no sampler "
       "of the program uses (unit 3; the sampler reads unit 0, empty): the draw succeeds.")
def feedback_loop_unused_unit(s):
    feedback_setup(s)
    s("activeTexture", "TEXTURE3")
    s("bindTexture", "TEXTURE_2D", R("tex"))
    s("activeTexture", "TEXTURE0")
    s("bindTexture", "TEXTURE_2D", None)
    draw(s)
    read(s, "texel00")
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("feedback-loop-other-level", "Level 1 of a two-level texture attached while the program samples it with "
       "TEXTURE_BASE_LEVEL = TEXTURE_MAX_LEVEL = 0: the levels do not overlap, so no feedback loop (level 1 "
       "gets level 0's colour); "
       "then attaching level 0 makes the draw INVALID_OPERATION.")
def feedback_loop_other_level(s):
    feedback_setup(s, levels=2)
    s("texParameteri", "TEXTURE_2D", "TEXTURE_MAX_LEVEL", 0)
    s("framebufferTexture2D", "FRAMEBUFFER", "COLOR_ATTACHMENT0", "TEXTURE_2D", R("tex"), 1)
    s("viewport", 0, 0, 2, 2)
    draw(s)
    read(s, "level1.texel00")
    s("framebufferTexture2D", "FRAMEBUFFER", "COLOR_ATTACHMENT0", "TEXTURE_2D", R("tex"), 0)
    draw(s, error="INVALID_OPERATION")
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("feedback-loop-copy", "copyTexSubImage2D from a framebuffer whose read attachment is the destination "
       "level is INVALID_OPERATION (a feedback loop); copying into another level is allowed.")
def feedback_loop_copy(s):
    s.texture("tex", "TEXTURE_2D", "RGBA8", 4, 4, levels=2)
    s.framebuffer("fb", [("COLOR_ATTACHMENT0", "tex", "TEXTURE_2D")])
    s("clearColor", 1, 0, 0, 1)
    s("clear", "COLOR_BUFFER_BIT")
    s("copyTexSubImage2D", "TEXTURE_2D", 0, 0, 0, 0, 0, 2, 2, error="INVALID_OPERATION")
    s("copyTexSubImage2D", "TEXTURE_2D", 1, 0, 0, 0, 0, 2, 2)
    s("bindFramebuffer", "FRAMEBUFFER", None)


# ---------------------------------------------------------------- draw with an incomplete framebuffer

@probe("draw-incomplete-framebuffer", "With an incomplete framebuffer bound (an RGBA32F attachment, no extension): "
       "drawArrays, drawElements, clear, clearBufferfv, readPixels and copyTexImage2D are "
       "INVALID_FRAMEBUFFER_OPERATION.")
def draw_incomplete_framebuffer(s):
    solid(s)
    s("createBuffer", as_="indices")
    s("bindBuffer", "ELEMENT_ARRAY_BUFFER", R("indices"))
    s("bufferData", "ELEMENT_ARRAY_BUFFER", U16([0, 1, 2]), "STATIC_DRAW")
    color_fb(s, "fb", "RGBA32F")
    draw(s, error="INVALID_FRAMEBUFFER_OPERATION")
    s("drawElements", "TRIANGLES", 3, "UNSIGNED_SHORT", 0, error="INVALID_FRAMEBUFFER_OPERATION")
    s("clear", "COLOR_BUFFER_BIT", error="INVALID_FRAMEBUFFER_OPERATION")
    s("clearBufferfv", "COLOR", 0, F32([1, 1, 1, 1]), error="INVALID_FRAMEBUFFER_OPERATION")
    s("readPixels", 0, 0, 1, 1, "RGBA", "FLOAT", OUT("f32", 4), error="INVALID_FRAMEBUFFER_OPERATION")
    s("createTexture", as_="copy")
    s("bindTexture", "TEXTURE_2D", R("copy"))
    s("copyTexImage2D", "TEXTURE_2D", 0, "RGBA8", 0, 0, 2, 2, 0, error="INVALID_FRAMEBUFFER_OPERATION")
    s("bindFramebuffer", "FRAMEBUFFER", None)


# ---------------------------------------------------------------- blitFramebuffer

def two_fbs(s, read_fmt="RGBA8", draw_fmt="RGBA8", size=4):
    color_fb(s, "src", read_fmt, size)
    color_fb(s, "dst", draw_fmt, size)
    s("bindFramebuffer", "READ_FRAMEBUFFER", R("src"))
    s("bindFramebuffer", "DRAW_FRAMEBUFFER", R("dst"))


def blit(s, mask="COLOR_BUFFER_BIT", filt="NEAREST", src=(0, 0, 4, 4), dst=(0, 0, 4, 4), error=None):
    s("blitFramebuffer", *src, *dst, mask, filt, error=error)


@probe("blit-format-mismatch", "blitFramebuffer between colour formats of different kinds: normalized to float "
       "and float to normalized are allowed, normalized to unsigned integer or signed to unsigned integer is "
       "INVALID_OPERATION, and LINEAR with integer formats is INVALID_OPERATION.",
       extensions=["EXT_color_buffer_float"])
def blit_format_mismatch(s):
    for name, internal in (("rgba8", "RGBA8"), ("rgba32f", "RGBA32F"), ("rgba8ui", "RGBA8UI"), ("rgba8i", "RGBA8I"),
                           ("r32ui", "R32UI")):
        color_fb(s, name, internal)
    for src, dst, error in (("rgba8", "rgba32f", None), ("rgba32f", "rgba8", None),
                            ("rgba8", "rgba8ui", "INVALID_OPERATION"),
                            ("rgba8i", "rgba8ui", "INVALID_OPERATION"), ("rgba8ui", "r32ui", None)):
        s("bindFramebuffer", "READ_FRAMEBUFFER", R(src))
        s("bindFramebuffer", "DRAW_FRAMEBUFFER", R(dst))
        blit(s, error=error)
    blit(s, filt="LINEAR", error="INVALID_OPERATION")
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("blit-depth-stencil", "Blitting depth or stencil: with LINEAR is INVALID_OPERATION; between different "
       "depth formats (DEPTH_COMPONENT24 to DEPTH_COMPONENT16) INVALID_OPERATION; between equal ones allowed; "
       "a mask bit that is not COLOR/DEPTH/STENCIL is INVALID_VALUE, a filter that is not NEAREST/LINEAR "
       "INVALID_ENUM.")
def blit_depth_stencil(s):
    s.texture("c1", "TEXTURE_2D", "RGBA8", 4, 4)
    s.texture("c2", "TEXTURE_2D", "RGBA8", 4, 4)
    for name, internal in (("d24a", "DEPTH_COMPONENT24"), ("d24b", "DEPTH_COMPONENT24"), ("d16", "DEPTH_COMPONENT16"),
                           ("ds", "DEPTH24_STENCIL8")):
        s.renderbuffer(name, internal, 4, 4)
    s.framebuffer("a", [("COLOR_ATTACHMENT0", "c1", "TEXTURE_2D"), ("DEPTH_ATTACHMENT", "d24a", "renderbuffer")])
    s.framebuffer("b", [("COLOR_ATTACHMENT0", "c2", "TEXTURE_2D"), ("DEPTH_ATTACHMENT", "d24b", "renderbuffer")])
    s("bindFramebuffer", "READ_FRAMEBUFFER", R("a"))
    s("bindFramebuffer", "DRAW_FRAMEBUFFER", R("b"))
    blit(s, mask="DEPTH_BUFFER_BIT")
    blit(s, mask="DEPTH_BUFFER_BIT", filt="LINEAR", error="INVALID_OPERATION")
    blit(s, mask=OR("COLOR_BUFFER_BIT", "DEPTH_BUFFER_BIT"), filt="LINEAR", error="INVALID_OPERATION")
    blit(s, mask="STENCIL_BUFFER_BIT")
    blit(s, mask=1, error="INVALID_VALUE")
    blit(s, filt="NEAREST_MIPMAP_NEAREST", error="INVALID_ENUM")
    s("framebufferRenderbuffer", "DRAW_FRAMEBUFFER", "DEPTH_ATTACHMENT", "RENDERBUFFER", R("d16"))
    blit(s, mask="DEPTH_BUFFER_BIT", error="INVALID_OPERATION")
    blit(s)
    s("framebufferRenderbuffer", "DRAW_FRAMEBUFFER", "DEPTH_STENCIL_ATTACHMENT", "RENDERBUFFER", R("ds"))
    blit(s, mask="DEPTH_BUFFER_BIT", error="INVALID_OPERATION")
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("blit-multisample-rules", "Blits with a 4-sample read framebuffer: a same-size resolve is allowed; "
       "with scaling, an offset destination, or a format difference (to RGB8) INVALID_OPERATION; into a "
       "multisampled draw framebuffer INVALID_OPERATION.")
def blit_multisample_rules(s):
    s.renderbuffer("msColor", "RGBA8", 4, 4, samples=4)
    s.renderbuffer("msColor2", "RGBA8", 4, 4, samples=4)
    s.framebuffer("ms", [("COLOR_ATTACHMENT0", "msColor", "renderbuffer")])
    s.framebuffer("ms2", [("COLOR_ATTACHMENT0", "msColor2", "renderbuffer")])
    color_fb(s, "single", "RGBA8", 8)
    color_fb(s, "rgb8", "RGB8", 4)
    s("bindFramebuffer", "READ_FRAMEBUFFER", R("ms"))
    s("bindFramebuffer", "DRAW_FRAMEBUFFER", R("single"))
    blit(s)
    blit(s, dst=(0, 0, 8, 8), error="INVALID_OPERATION")
    blit(s, dst=(1, 1, 5, 5), error="INVALID_OPERATION")
    blit(s, dst=(4, 0, 0, 4), error="INVALID_OPERATION")
    s("bindFramebuffer", "DRAW_FRAMEBUFFER", R("rgb8"))
    blit(s, error="INVALID_OPERATION")
    s("bindFramebuffer", "DRAW_FRAMEBUFFER", R("ms2"))
    blit(s, error="INVALID_OPERATION")
    s("bindFramebuffer", "READ_FRAMEBUFFER", R("single"))
    blit(s, error="INVALID_OPERATION")
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("blit-same-image", "Read and draw framebuffer on the same texture image: overlapping rectangles are "
       "INVALID_OPERATION; so are rectangles that do not overlap (WebGL 2 forbids the same image at all); "
       "another level of the same texture is fine.")
def blit_same_image(s):
    s.texture("tex", "TEXTURE_2D", "RGBA8", 8, 8, levels=2)
    s.framebuffer("a", [("COLOR_ATTACHMENT0", "tex", "TEXTURE_2D")])
    s.framebuffer("b", [("COLOR_ATTACHMENT0", "tex", "TEXTURE_2D")])
    s("bindFramebuffer", "READ_FRAMEBUFFER", R("a"))
    s("bindFramebuffer", "DRAW_FRAMEBUFFER", R("b"))
    blit(s, src=(0, 0, 4, 4), dst=(2, 2, 6, 6), error="INVALID_OPERATION")
    blit(s, src=(0, 0, 4, 4), dst=(4, 4, 8, 8), error="INVALID_OPERATION")
    s("bindFramebuffer", "READ_FRAMEBUFFER", R("a"))
    s("bindFramebuffer", "DRAW_FRAMEBUFFER", R("a"))
    blit(s, src=(0, 0, 4, 4), dst=(4, 4, 8, 8), error="INVALID_OPERATION")
    s("framebufferTexture2D", "DRAW_FRAMEBUFFER", "COLOR_ATTACHMENT0", "TEXTURE_2D", R("tex"), 1)
    s("checkFramebufferStatus", "DRAW_FRAMEBUFFER", record="drawLevel1.status")
    s("bindFramebuffer", "READ_FRAMEBUFFER", R("b"))
    blit(s, src=(0, 0, 8, 8), dst=(0, 0, 4, 4), filt="LINEAR")
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("blit-scale-flip", "What a blit writes: a 4x4 RGBA8 source with four coloured quadrants (cleared with "
       "scissor) blitted mirrored in x and y, and stretched 2x with NEAREST; pixels read back.")
def blit_scale_flip(s):
    two_fbs(s, size=8)
    s("bindFramebuffer", "FRAMEBUFFER", R("src"))
    s("enable", "SCISSOR_TEST")
    for (x, y), c in (((0, 0), [1, 0, 0, 1]), ((2, 0), [0, 1, 0, 1]), ((0, 2), [0, 0, 1, 1]), ((2, 2), [1, 1, 1, 1])):
        s("scissor", x, y, 2, 2)
        s("clearBufferfv", "COLOR", 0, F32(c))
    s("disable", "SCISSOR_TEST")
    s("bindFramebuffer", "READ_FRAMEBUFFER", R("src"))
    s("bindFramebuffer", "DRAW_FRAMEBUFFER", R("dst"))
    blit(s, src=(0, 0, 4, 4), dst=(4, 4, 0, 0))
    s("bindFramebuffer", "READ_FRAMEBUFFER", R("dst"))
    s("readPixels", 0, 0, 4, 4, "RGBA", "UNSIGNED_BYTE", OUT("u8", 64), record="mirrored")
    s("bindFramebuffer", "READ_FRAMEBUFFER", R("src"))
    blit(s, src=(0, 0, 4, 4), dst=(0, 0, 8, 8))
    s("bindFramebuffer", "READ_FRAMEBUFFER", R("dst"))
    s("readPixels", 0, 0, 8, 1, "RGBA", "UNSIGNED_BYTE", OUT("u8", 32), record="stretchedRow0")
    s("bindFramebuffer", "DRAW_FRAMEBUFFER", None)
    blit(s, src=(0, 0, 8, 8), dst=(0, 0, 16, 16))
    s("bindFramebuffer", "FRAMEBUFFER", None)


# ---------------------------------------------------------------- readPixels

def read_formats(s, prefix):
    s("getParameter", "IMPLEMENTATION_COLOR_READ_FORMAT", record=f"{prefix}.readFormat")
    s("getParameter", "IMPLEMENTATION_COLOR_READ_TYPE", record=f"{prefix}.readType")


@probe("readpixels-rgba8", "readPixels from an RGBA8 texture: IMPLEMENTATION_COLOR_READ_FORMAT/TYPE; "
       "RGBA/UNSIGNED_BYTE works; RGB/UNSIGNED_BYTE, RGBA/FLOAT, RGBA_INTEGER, RGBA/UNSIGNED_SHORT are "
       "INVALID_OPERATION; a Float32Array for UNSIGNED_BYTE is INVALID_OPERATION; a buffer too small is "
       "INVALID_OPERATION; an unknown format INVALID_ENUM.")
def readpixels_rgba8(s):
    color_fb(s, "fb", "RGBA8")
    s("clearColor", 0.2, 0.4, 0.6, 0.8)
    s("clear", "COLOR_BUFFER_BIT")
    read_formats(s, "rgba8")
    read(s, "RGBA.UNSIGNED_BYTE")
    read(s, "RGB.UNSIGNED_BYTE", fmt="RGB", error="INVALID_OPERATION")
    read(s, "RGBA.FLOAT", kind="FLOAT", out="f32", error="INVALID_OPERATION")
    read(s, "RGBA_INTEGER.UNSIGNED_INT", fmt="RGBA_INTEGER", kind="UNSIGNED_INT", out="u32", error="INVALID_OPERATION")
    read(s, "RGBA.UNSIGNED_SHORT", kind="UNSIGNED_SHORT", out="u16", error="INVALID_OPERATION")
    read(s, "RGBA.UNSIGNED_BYTE.intoFloat32Array", out="f32", error="INVALID_OPERATION")
    s("readPixels", 0, 0, 2, 2, "RGBA", "UNSIGNED_BYTE", OUT("u8", 15), error="INVALID_OPERATION")
    read(s, "DEPTH_COMPONENT", fmt="DEPTH_COMPONENT", kind="UNSIGNED_INT", out="u32", error="INVALID_ENUM")
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("readpixels-rgb565-rgba4", "IMPLEMENTATION_COLOR_READ_FORMAT/TYPE for RGB565, RGBA4 and RGB8 textures "
       "(RGB/UNSIGNED_SHORT_5_6_5, "
       "RGBA/UNSIGNED_SHORT_4_4_4_4, RGBA/UNSIGNED_BYTE), readPixels with RGBA/UNSIGNED_BYTE (the values "
       "quantised to the format's bits) and with the packed pair; RGB/UNSIGNED_BYTE from RGB8 is "
       "INVALID_OPERATION.")
def readpixels_rgb565(s):
    for name, internal, fmt, kind, error in (("rgb565", "RGB565", "RGB", "UNSIGNED_SHORT_5_6_5", None),
                                             ("rgba4", "RGBA4", "RGBA", "UNSIGNED_SHORT_4_4_4_4", None),
                                             ("rgb8", "RGB8", "RGB", "UNSIGNED_BYTE", "INVALID_OPERATION")):
        color_fb(s, name, internal)
        s("clearColor", 1.0, 0.45, 0.2, 1.0)
        s("clear", "COLOR_BUFFER_BIT")
        read_formats(s, name)
        read(s, f"{name}.RGBA.UNSIGNED_BYTE")
        read(s, f"{name}.{fmt}.{kind}", fmt=fmt, kind=kind, out="u16" if "SHORT" in kind else "u8", error=error)
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("readpixels-r32ui", "readPixels from an R32UI attachment: IMPLEMENTATION_COLOR_READ_FORMAT/TYPE; "
       "RGBA_INTEGER/UNSIGNED_INT and the implementation's pair work; RGBA/UNSIGNED_BYTE and "
       "RGBA_INTEGER/INT are INVALID_OPERATION.")
def readpixels_r32ui(s):
    color_fb(s, "fb", "R32UI")
    s("clearBufferuiv", "COLOR", 0, U32([4000000000, 5, 6, 7]))
    read_formats(s, "r32ui")
    read(s, "RGBA_INTEGER.UNSIGNED_INT", fmt="RGBA_INTEGER", kind="UNSIGNED_INT", out="u32")
    s("readPixels", 0, 0, 1, 1, "RED_INTEGER", "UNSIGNED_INT", OUT("u32", 1), record="RED_INTEGER.UNSIGNED_INT")
    read(s, "RGBA.UNSIGNED_BYTE", error="INVALID_OPERATION")
    read(s, "RGBA_INTEGER.INT", fmt="RGBA_INTEGER", kind="INT", out="i32", error="INVALID_OPERATION")
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("readpixels-rgba8i", "readPixels from an RGBA8I attachment: the implementation's format/type, "
       "RGBA_INTEGER/INT works and gives the signed values, RGBA_INTEGER/UNSIGNED_INT is INVALID_OPERATION.")
def readpixels_rgba8i(s):
    color_fb(s, "fb", "RGBA8I")
    s("clearBufferiv", "COLOR", 0, I32([-5, 100, -128, 127]))
    read_formats(s, "rgba8i")
    read(s, "RGBA_INTEGER.INT", fmt="RGBA_INTEGER", kind="INT", out="i32")
    read(s, "RGBA_INTEGER.UNSIGNED_INT", fmt="RGBA_INTEGER", kind="UNSIGNED_INT", out="u32", error="INVALID_OPERATION")
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("readpixels-rgba32f", "readPixels from RGBA32F and RGBA16F attachments (EXT_color_buffer_float): "
       "IMPLEMENTATION_COLOR_READ_FORMAT/TYPE; RGBA/FLOAT works and keeps values outside [0, 1]; "
       "RGBA/UNSIGNED_BYTE is INVALID_OPERATION.", extensions=["EXT_color_buffer_float"])
def readpixels_rgba32f(s):
    for name, internal, big in (("rgba32f", "RGBA32F", 1e6), ("rgba16f", "RGBA16F", 1000)):
        color_fb(s, name, internal)
        s("clearBufferfv", "COLOR", 0, F32([-1.5, 0.25, 2.0, big]))
        read_formats(s, name)
        read(s, f"{name}.RGBA.FLOAT", kind="FLOAT", out="f32")
        read(s, f"{name}.RGBA.UNSIGNED_BYTE", error="INVALID_OPERATION")
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("readpixels-outside", "readPixels of a rectangle partly outside the framebuffer: the pixels outside are "
       "left as they were in the destination (WebGL; here pre-filled with 7), the inside ones read; a negative "
       "width is INVALID_VALUE.")
def readpixels_outside(s):
    color_fb(s, "fb", "RGBA8", 2)
    s("clearColor", 1, 1, 1, 1)
    s("clear", "COLOR_BUFFER_BIT")
    s("readPixels", -1, 1, 3, 2, "RGBA", "UNSIGNED_BYTE", OUT("u8", 24, fill=7), record="partlyOutside")
    s("readPixels", 0, 0, -1, 1, "RGBA", "UNSIGNED_BYTE", OUT("u8", 4), error="INVALID_VALUE")
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("readpixels-read-buffer", "readBuffer rules: on the default framebuffer BACK and NONE are accepted, "
       "COLOR_ATTACHMENT0 is INVALID_OPERATION; on a framebuffer COLOR_ATTACHMENT1 selects the second target, "
       "BACK is INVALID_OPERATION, and after readBuffer(NONE) readPixels is INVALID_OPERATION.")
def readpixels_read_buffer(s):
    s("readBuffer", "COLOR_ATTACHMENT0", error="INVALID_OPERATION")
    s("readBuffer", "NONE")
    s("getParameter", "READ_BUFFER", record="default.afterNone")
    s("readBuffer", "BACK")
    s.texture("a", "TEXTURE_2D", "RGBA8", 2, 2)
    s.texture("b", "TEXTURE_2D", "RGBA8", 2, 2)
    s.framebuffer("fb", [("COLOR_ATTACHMENT0", "a", "TEXTURE_2D"), ("COLOR_ATTACHMENT1", "b", "TEXTURE_2D")])
    s("getParameter", "READ_BUFFER", record="fb.initial")
    s("clearBufferfv", "COLOR", 0, F32([1, 0, 0, 1]))
    s("drawBuffers", ["NONE", "COLOR_ATTACHMENT1"])
    s("clearBufferfv", "COLOR", 1, F32([0, 1, 0, 1]))
    s("readBuffer", "BACK", error="INVALID_OPERATION")
    s("readBuffer", "COLOR_ATTACHMENT1")
    read(s, "attachment1")
    s("readBuffer", "COLOR_ATTACHMENT0")
    read(s, "attachment0")
    s("readBuffer", "NONE")
    read(s, "none", error="INVALID_OPERATION")
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("readpixels-pack-buffer", "readPixels into a PIXEL_PACK_BUFFER at an offset, then getBufferSubData; an "
       "ArrayBufferView while a pack buffer is bound, or an offset while none is, is INVALID_OPERATION.")
def readpixels_pack_buffer(s):
    color_fb(s, "fb", "RGBA8", 2)
    s("clearColor", 0.0, 0.2, 0.4, 1.0)
    s("clear", "COLOR_BUFFER_BIT")
    s("createBuffer", as_="pack")
    s("bindBuffer", "PIXEL_PACK_BUFFER", R("pack"))
    s("bufferData", "PIXEL_PACK_BUFFER", 24, "STREAM_READ")
    s("readPixels", 0, 0, 2, 2, "RGBA", "UNSIGNED_BYTE", 8)
    s("readPixels", 0, 0, 1, 1, "RGBA", "UNSIGNED_BYTE", OUT("u8", 4), error="INVALID_OPERATION")
    s("getBufferSubData", "PIXEL_PACK_BUFFER", 0, OUT("u8", 24), record="packBuffer")
    s("bindBuffer", "PIXEL_PACK_BUFFER", None)
    s("readPixels", 0, 0, 1, 1, "RGBA", "UNSIGNED_BYTE", 0, error="INVALID_OPERATION")
    s("bindFramebuffer", "FRAMEBUFFER", None)


# ---------------------------------------------------------------- clearBuffer*

@probe("clearbuffer-wrong-type", "clearBuffer* must match the attachment: clearBufferfv on R32UI, clearBufferuiv "
       "on RGBA8 and clearBufferiv on RGBA8UI are INVALID_OPERATION; clear(COLOR_BUFFER_BIT) with an integer "
       "draw buffer is INVALID_OPERATION (WebGL); clearBufferfi(COLOR) is INVALID_ENUM; a draw buffer index "
       "past MAX_DRAW_BUFFERS or non-zero for DEPTH is INVALID_VALUE; a value array too short is INVALID_VALUE.")
def clearbuffer_wrong_type(s):
    s.texture("norm", "TEXTURE_2D", "RGBA8", 2, 2)
    s.texture("uint", "TEXTURE_2D", "R32UI", 2, 2)
    s.texture("uint8", "TEXTURE_2D", "RGBA8UI", 2, 2)
    s.renderbuffer("depth", "DEPTH_COMPONENT16", 2, 2)
    s.framebuffer("fb", [("COLOR_ATTACHMENT0", "norm", "TEXTURE_2D"), ("COLOR_ATTACHMENT1", "uint", "TEXTURE_2D"),
                         ("COLOR_ATTACHMENT2", "uint8", "TEXTURE_2D"), ("DEPTH_ATTACHMENT", "depth", "renderbuffer")])
    s("drawBuffers", ["COLOR_ATTACHMENT0", "COLOR_ATTACHMENT1", "COLOR_ATTACHMENT2"])
    s("clearBufferfv", "COLOR", 0, F32([0.6, 0.6, 0.6, 1]))
    s("clearBufferuiv", "COLOR", 1, U32([9, 0, 0, 0]))
    s("clearBufferuiv", "COLOR", 2, U32([1, 2, 3, 4]))
    s("clearBufferfv", "COLOR", 1, F32([1, 1, 1, 1]), error="INVALID_OPERATION")
    s("clearBufferuiv", "COLOR", 0, U32([1, 1, 1, 1]), error="INVALID_OPERATION")
    s("clearBufferiv", "COLOR", 2, I32([1, 1, 1, 1]), error="INVALID_OPERATION")
    s("clear", "COLOR_BUFFER_BIT", error="INVALID_OPERATION")
    s("clear", "DEPTH_BUFFER_BIT")
    s("clearBufferfi", "COLOR", 0, 1.0, 0, error="INVALID_ENUM")
    s("clearBufferfv", "COLOR", 8, F32([1, 1, 1, 1]), error="INVALID_VALUE")
    s("clearBufferfv", "DEPTH", 1, F32([1]), error="INVALID_VALUE")
    s("clearBufferfv", "COLOR", 0, F32([1, 1]), error="INVALID_VALUE")
    s("clearBufferiv", "DEPTH", 0, I32([1]), error="INVALID_ENUM")
    s("readBuffer", "COLOR_ATTACHMENT1")
    read(s, "uint.afterAll", fmt="RGBA_INTEGER", kind="UNSIGNED_INT", out="u32")
    s("readBuffer", "COLOR_ATTACHMENT0")
    read(s, "norm.afterAll")
    s("drawBuffers", ["COLOR_ATTACHMENT0", "NONE", "NONE"])
    s("clearColor", 1, 0, 0, 1)
    s("clear", "COLOR_BUFFER_BIT")
    read(s, "norm.clearedWithIntegerBuffersOff")
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("clearbuffer-scissor-mask", "clearBufferfv honours the scissor test and the colour mask; "
       "clear with RASTERIZER_DISCARD enabled changes nothing.")
def clearbuffer_scissor_mask(s):
    color_fb(s, "fb", "RGBA8", 4)
    s("clearBufferfv", "COLOR", 0, F32([0, 0, 0, 1]))
    s("enable", "SCISSOR_TEST")
    s("scissor", 2, 2, 2, 2)
    s("colorMask", True, False, True, True)
    s("clearBufferfv", "COLOR", 0, F32([1, 1, 1, 1]))
    s("disable", "SCISSOR_TEST")
    s("colorMask", True, True, True, True)
    s("readPixels", 0, 0, 4, 4, "RGBA", "UNSIGNED_BYTE", OUT("u8", 64), record="afterScissoredMaskedClear")
    s("enable", "RASTERIZER_DISCARD")
    s("clearColor", 0, 1, 0, 1)
    s("clear", "COLOR_BUFFER_BIT")
    s("clearBufferfv", "COLOR", 0, F32([0, 0, 1, 1]))
    s("disable", "RASTERIZER_DISCARD")
    read(s, "afterDiscardedClears")
    s("bindFramebuffer", "FRAMEBUFFER", None)


# ---------------------------------------------------------------- draw buffers

@probe("drawbuffers-rules", "drawBuffers rules: on the default framebuffer [BACK] and [NONE] are accepted, "
       "[COLOR_ATTACHMENT0] and two entries are INVALID_OPERATION; on a framebuffer entry i must be "
       "COLOR_ATTACHMENTi or NONE (else INVALID_OPERATION), BACK is INVALID_OPERATION, more than "
       "MAX_DRAW_BUFFERS entries INVALID_VALUE; DRAW_BUFFERi answers.")
def drawbuffers_rules(s):
    s("getParameter", "DRAW_BUFFER0", record="default.DRAW_BUFFER0")
    s("drawBuffers", ["COLOR_ATTACHMENT0"], error="INVALID_OPERATION")
    s("drawBuffers", ["BACK", "NONE"], error="INVALID_OPERATION")
    s("drawBuffers", ["NONE"])
    s("getParameter", "DRAW_BUFFER0", record="default.afterNone")
    s("drawBuffers", ["BACK"])
    s("createFramebuffer", as_="fb")
    s("bindFramebuffer", "FRAMEBUFFER", R("fb"))
    s("getParameter", "DRAW_BUFFER0", record="fb.DRAW_BUFFER0")
    s("getParameter", "DRAW_BUFFER1", record="fb.DRAW_BUFFER1")
    s("drawBuffers", ["COLOR_ATTACHMENT1", "COLOR_ATTACHMENT0"], error="INVALID_OPERATION")
    s("drawBuffers", ["BACK"], error="INVALID_OPERATION")
    s("drawBuffers", ["NONE", "COLOR_ATTACHMENT1", "NONE", "COLOR_ATTACHMENT3"])
    for i in range(5):
        s("getParameter", f"DRAW_BUFFER{i}", record=f"fb.after.DRAW_BUFFER{i}")
    s("drawBuffers", ["NONE"] * 9, error="INVALID_VALUE")
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("draw-output-mismatch", "A draw whose fragment outputs do not fit the draw buffers: an unsigned-integer "
       "output into RGBA8, a float output into R32UI, and a second draw buffer the shader does not write are "
       "INVALID_OPERATION; with that buffer NONE, or colorMask all false, the draw goes through.")
def draw_output_mismatch(s):
    program(s, "uint", "probes/uint-out.frag")
    solid(s)
    s.texture("normTex", "TEXTURE_2D", "RGBA8", 2, 2)
    s.texture("uintTex", "TEXTURE_2D", "RGBA8UI", 2, 2)
    s.framebuffer("normFb", [("COLOR_ATTACHMENT0", "normTex", "TEXTURE_2D")])
    s("viewport", 0, 0, 2, 2)
    s("useProgram", R("uint"))
    draw(s, error="INVALID_OPERATION")
    s.framebuffer("uintFb", [("COLOR_ATTACHMENT0", "uintTex", "TEXTURE_2D")])
    draw(s)
    read(s, "uint.written", fmt="RGBA_INTEGER", kind="UNSIGNED_INT", out="u32")
    s("useProgram", R("solid"))
    draw(s, error="INVALID_OPERATION")
    s.texture("second", "TEXTURE_2D", "RGBA8", 2, 2)
    s.framebuffer("twoFb", [("COLOR_ATTACHMENT0", "normTex", "TEXTURE_2D"),
                            ("COLOR_ATTACHMENT1", "second", "TEXTURE_2D")])
    s("drawBuffers", ["COLOR_ATTACHMENT0", "COLOR_ATTACHMENT1"])
    draw(s, error="INVALID_OPERATION")
    s("drawBuffers", ["COLOR_ATTACHMENT0", "NONE"])
    draw(s)
    s("drawBuffers", ["COLOR_ATTACHMENT0", "COLOR_ATTACHMENT1"])
    s("colorMask", False, False, False, False)
    draw(s)
    s("colorMask", True, True, True, True)
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("draw-depth-only-no-outputs", "A framebuffer with only a depth attachment and the default draw buffers "
       "(COLOR_ATTACHMENT0, nothing attached there), drawn with a shader without outputs: allowed.")
def draw_depth_only(s):
    program(s, "empty", "common-empty.frag")
    s.texture("depth", "TEXTURE_2D", "DEPTH_COMPONENT16", 4, 4)
    s.framebuffer("fb", [("DEPTH_ATTACHMENT", "depth", "TEXTURE_2D")])
    s("getParameter", "DRAW_BUFFER0", record="fb.DRAW_BUFFER0")
    s("viewport", 0, 0, 4, 4)
    s("useProgram", R("empty"))
    s("enable", "DEPTH_TEST")
    draw(s)
    s("disable", "DEPTH_TEST")
    s("bindFramebuffer", "FRAMEBUFFER", None)


# ---------------------------------------------------------------- sampler types

@probe("sampler-type-mismatch", "Draws whose sampler type does not fit the texture: usampler2D over RGBA8 and "
       "sampler2D over R32UI are INVALID_OPERATION; so are sampler2DShadow over a depth texture without "
       "TEXTURE_COMPARE_MODE and sampler2D over one with it (undefined results in ES 3.0; Chromium "
       "rejects them); sampler2DShadow with COMPARE_REF_TO_TEXTURE draws.")
def sampler_type_mismatch(s):
    for name, frag in (("float", "probes/sample.frag"), ("uint", "probes/sample-uint.frag"),
                       ("shadow", "probes/sample-shadow.frag")):
        program(s, name, frag, uniforms=["u_texture"])
    s.texture("rgba8", "TEXTURE_2D", "RGBA8", 2, 2)
    s.texture("r32ui", "TEXTURE_2D", "R32UI", 2, 2)
    s.texture("depth", "TEXTURE_2D", "DEPTH_COMPONENT16", 2, 2)
    s("useProgram", R("uint"))
    s("bindTexture", "TEXTURE_2D", R("rgba8"))
    draw(s, error="INVALID_OPERATION")
    s("bindTexture", "TEXTURE_2D", R("r32ui"))
    draw(s)
    s("useProgram", R("float"))
    draw(s, error="INVALID_OPERATION")
    s("useProgram", R("shadow"))
    s("bindTexture", "TEXTURE_2D", R("depth"))
    draw(s, error="INVALID_OPERATION")
    s("texParameteri", "TEXTURE_2D", "TEXTURE_COMPARE_MODE", "COMPARE_REF_TO_TEXTURE")
    draw(s)
    s("useProgram", R("float"))
    draw(s, error="INVALID_OPERATION")


# ---------------------------------------------------------------- stencil

@probe("stencil-separate-mismatch", "WebGL requires the front and back stencil reference and masks to agree at "
       "draw time, while STENCIL_TEST is enabled (a mismatch with it disabled draws): stencilFuncSeparate "
       "with refs 1 and 2, or value masks 0xFF and 0x0F, or stencilMaskSeparate with different write masks, "
       "make drawArrays INVALID_OPERATION; so do refs 1 and 257 (257 clamps to 255); masks 0xFF and 0x1FF "
       "agree (compared within the 8 stencil bits).", context={"stencil": True})
def stencil_separate_mismatch(s):
    solid(s)
    s("getParameter", "STENCIL_BITS", record="STENCIL_BITS")
    s("stencilFuncSeparate", "FRONT", "ALWAYS", 1, 255)
    s("stencilFuncSeparate", "BACK", "ALWAYS", 2, 255)
    draw(s)
    s("enable", "STENCIL_TEST")
    draw(s, error="INVALID_OPERATION")
    s("stencilFuncSeparate", "BACK", "ALWAYS", 1, 15)
    draw(s, error="INVALID_OPERATION")
    s("stencilFuncSeparate", "BACK", "ALWAYS", 1, 255)
    s("stencilMaskSeparate", "BACK", 15)
    draw(s, error="INVALID_OPERATION")
    s("stencilMaskSeparate", "BACK", 255)
    draw(s)
    s("stencilFuncSeparate", "BACK", "ALWAYS", 257, 255)
    draw(s, error="INVALID_OPERATION")
    s("stencilFuncSeparate", "BACK", "ALWAYS", 1, 511)
    draw(s)
    s("getParameter", "STENCIL_BACK_VALUE_MASK", record="STENCIL_BACK_VALUE_MASK")
    s("getParameter", "STENCIL_BACK_REF", record="STENCIL_BACK_REF")
    s("stencilFuncSeparate", "FRONT_AND_BACK", "ALWAYS", 3, 255)
    draw(s)


@probe("stencil-separate-no-stencil-buffer", "The same front/back mismatch with STENCIL_TEST enabled but no "
       "stencil buffer (context stencil: false): with 0 stencil bits the check always passes.")
def stencil_separate_no_stencil(s):
    solid(s)
    s("getParameter", "STENCIL_BITS", record="STENCIL_BITS")
    s("enable", "STENCIL_TEST")
    s("stencilFuncSeparate", "FRONT", "ALWAYS", 1, 255)
    s("stencilFuncSeparate", "BACK", "ALWAYS", 2, 255)
    draw(s)
    s("stencilMaskSeparate", "BACK", 15)
    draw(s)


@probe("stencil-draw", "What stencil does: a 2x2 scissored clear of the stencil to 1 (clearBufferiv), then a "
       "full-canvas draw with stencilFunc(EQUAL, 1) and stencilOp INCR, then one with stencilFunc(LESS, 1) "
       "(ref < stored); pixels read back.", context={"stencil": True})
def stencil_draw(s):
    solid(s, color=(1, 0, 0, 1))
    s("clearBufferfv", "COLOR", 0, F32([0, 0, 0, 1]))
    s("clearBufferiv", "STENCIL", 0, I32([0]))
    s("enable", "SCISSOR_TEST")
    s("scissor", 0, 0, 8, 8)
    s("clearBufferiv", "STENCIL", 0, I32([1]))
    s("disable", "SCISSOR_TEST")
    s("enable", "STENCIL_TEST")
    s("stencilFunc", "EQUAL", 1, 255)
    s("stencilOp", "KEEP", "KEEP", "INCR")
    draw(s)
    s("uniform4fv", R("solid.u_color"), F32([0, 0, 1, 1]))
    s("stencilFunc", "LESS", 1, 255)
    s("stencilOp", "KEEP", "KEEP", "KEEP")
    draw(s)
    s("disable", "STENCIL_TEST")
    read(s, "inside", 2, 2)
    read(s, "outside", 12, 12)


# ---------------------------------------------------------------- samplers

@probe("sampler-parameters", "Sampler objects: the initial parameters (getSamplerParameter), errors for a "
       "texture-only pname (TEXTURE_BASE_LEVEL, INVALID_ENUM), a bad value (MIN_FILTER = REPEAT, INVALID_ENUM), "
       "a bad compare function (INVALID_ENUM), bindSampler past MAX_COMBINED_TEXTURE_IMAGE_UNITS "
       "(INVALID_VALUE), a deleted sampler (INVALID_OPERATION), SAMPLER_BINDING answers.")
def sampler_parameters(s):
    s("createSampler", as_="smp")
    for p in ("TEXTURE_MIN_FILTER", "TEXTURE_MAG_FILTER", "TEXTURE_WRAP_S", "TEXTURE_WRAP_T", "TEXTURE_WRAP_R",
              "TEXTURE_MIN_LOD", "TEXTURE_MAX_LOD", "TEXTURE_COMPARE_MODE", "TEXTURE_COMPARE_FUNC"):
        s("getSamplerParameter", R("smp"), p, record=f"initial.{p}")
    s("samplerParameteri", R("smp"), "TEXTURE_BASE_LEVEL", 1, error="INVALID_ENUM")
    s("samplerParameteri", R("smp"), "TEXTURE_MIN_FILTER", "REPEAT", error="INVALID_ENUM")
    s("samplerParameteri", R("smp"), "TEXTURE_MAG_FILTER", "LINEAR_MIPMAP_LINEAR", error="INVALID_ENUM")
    s("samplerParameteri", R("smp"), "TEXTURE_COMPARE_FUNC", "LINEAR", error="INVALID_ENUM")
    s("samplerParameteri", R("smp"), "TEXTURE_WRAP_S", "NEAREST", error="INVALID_ENUM")
    s("samplerParameterf", R("smp"), "TEXTURE_MIN_LOD", 2.5)
    s("samplerParameterf", R("smp"), "TEXTURE_MAX_LOD", -3.0)
    s("samplerParameteri", R("smp"), "TEXTURE_WRAP_R", "MIRRORED_REPEAT")
    s("getSamplerParameter", R("smp"), "TEXTURE_MIN_LOD", record="set.TEXTURE_MIN_LOD")
    s("getSamplerParameter", R("smp"), "TEXTURE_MAX_LOD", record="set.TEXTURE_MAX_LOD")
    s("getSamplerParameter", R("smp"), "TEXTURE_WRAP_R", record="set.TEXTURE_WRAP_R")
    s("getSamplerParameter", R("smp"), "TEXTURE_MAX_LEVEL", error="INVALID_ENUM", record="get.TEXTURE_MAX_LEVEL")
    s("getParameter", "MAX_COMBINED_TEXTURE_IMAGE_UNITS", record="MAX_COMBINED_TEXTURE_IMAGE_UNITS")
    s("bindSampler", 1000, R("smp"), error="INVALID_VALUE")
    s("activeTexture", "TEXTURE2")
    s("bindSampler", 2, R("smp"))
    s("getParameter", "SAMPLER_BINDING", record="unit2.SAMPLER_BINDING")
    s("activeTexture", "TEXTURE0")
    s("getParameter", "SAMPLER_BINDING", record="unit0.SAMPLER_BINDING")
    s("isSampler", R("smp"), record="isSampler")
    s("deleteSampler", R("smp"))
    s("isSampler", R("smp"), record="isSampler.deleted")
    s("activeTexture", "TEXTURE2")
    s("getParameter", "SAMPLER_BINDING", record="unit2.afterDelete")
    s("activeTexture", "TEXTURE0")
    s("bindSampler", 0, R("smp"), error="INVALID_OPERATION")
    s("samplerParameteri", R("smp"), "TEXTURE_MIN_FILTER", "LINEAR", error="INVALID_OPERATION")


@probe("sampler-overrides-texture", "A sampler object bound to a unit replaces the texture's own filtering: a "
       "2x1 black/white texture with NEAREST filters, drawn over 16x16 with a LINEAR sampler bound (the "
       "middle columns blend) and after bindSampler(0, null) (a hard edge); a row of pixels read each time.",
       width=16, height=4)
def sampler_overrides_texture(s):
    program(s, "show", "probes/sample.frag", uniforms=["u_texture"])
    s("useProgram", R("show"))
    s("createTexture", as_="tex")
    s("bindTexture", "TEXTURE_2D", R("tex"))
    s("texImage2D", "TEXTURE_2D", 0, "RGBA8", 2, 1, 0, "RGBA", "UNSIGNED_BYTE",
      {"u8": [0, 0, 0, 255, 255, 255, 255, 255]})
    for p, v in (("TEXTURE_MIN_FILTER", "NEAREST"), ("TEXTURE_MAG_FILTER", "NEAREST"),
                 ("TEXTURE_WRAP_S", "CLAMP_TO_EDGE"), ("TEXTURE_WRAP_T", "CLAMP_TO_EDGE")):
        s("texParameteri", "TEXTURE_2D", p, v)
    s("createSampler", as_="linear")
    for p, v in (("TEXTURE_MIN_FILTER", "LINEAR"), ("TEXTURE_MAG_FILTER", "LINEAR"),
                 ("TEXTURE_WRAP_S", "CLAMP_TO_EDGE"), ("TEXTURE_WRAP_T", "CLAMP_TO_EDGE")):
        s("samplerParameteri", R("linear"), p, v)
    s("bindSampler", 0, R("linear"))
    draw(s)
    s("readPixels", 0, 0, 16, 1, "RGBA", "UNSIGNED_BYTE", OUT("u8", 64), record="withLinearSampler")
    s("bindSampler", 0, None)
    s("viewport", 0, 2, 16, 2)
    draw(s)
    s("readPixels", 0, 2, 16, 1, "RGBA", "UNSIGNED_BYTE", OUT("u8", 64), record="withoutSampler")


# ---------------------------------------------------------------- queries

@probe("query-misuse", "Query errors: endQuery with none active, beginQuery while one of the same target is "
       "active, ANY_SAMPLES_PASSED_CONSERVATIVE while ANY_SAMPLES_PASSED is active (one occlusion target), "
       "beginQuery on a query used for another target, getQueryParameter of an active query, and a bad "
       "target, are INVALID_OPERATION / INVALID_ENUM; getQuery(CURRENT_QUERY) answers.")
def query_misuse(s):
    s("createQuery", as_="a")
    s("createQuery", as_="b")
    s("endQuery", "ANY_SAMPLES_PASSED", error="INVALID_OPERATION")
    s("getQuery", "ANY_SAMPLES_PASSED", "CURRENT_QUERY", record="before")
    s("isQuery", R("a"), record="isQuery.beforeBegin")
    s("beginQuery", "ANY_SAMPLES_PASSED", R("a"))
    s("isQuery", R("a"), record="isQuery.afterBegin")
    s("getQuery", "ANY_SAMPLES_PASSED", "CURRENT_QUERY", record="during")
    s("getQuery", "ANY_SAMPLES_PASSED_CONSERVATIVE", "CURRENT_QUERY", record="during.conservative")
    s("beginQuery", "ANY_SAMPLES_PASSED", R("b"), error="INVALID_OPERATION")
    s("beginQuery", "ANY_SAMPLES_PASSED_CONSERVATIVE", R("b"), error="INVALID_OPERATION")
    s("beginQuery", "TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN", R("a"), error="INVALID_OPERATION")
    s("getQueryParameter", R("a"), "QUERY_RESULT_AVAILABLE", error="INVALID_OPERATION", record="activeAvailable")
    s("endQuery", "ANY_SAMPLES_PASSED")
    s("beginQuery", "ANY_SAMPLES_PASSED_CONSERVATIVE", R("a"), error="INVALID_OPERATION")
    s("beginQuery", "TEXTURE_2D", R("b"), error="INVALID_ENUM")
    s("getQuery", "ANY_SAMPLES_PASSED", "QUERY_RESULT", error="INVALID_ENUM", record="getQuery.QUERY_RESULT")
    s("deleteQuery", R("b"))
    s("beginQuery", "ANY_SAMPLES_PASSED", R("b"), error="INVALID_OPERATION")


@probe("query-results", "Occlusion query results: not available in the task that issued them, even after "
       "finish() (WebGL); available after returning to the event loop (`until`); 1 for a draw that passes "
       "the depth test, 0 for one that fails it (depth func NEVER); QUERY_RESULT of a query that was never "
       "ended? (not asked).")
def query_results(s):
    solid(s)
    s("createQuery", as_="passes")
    s("createQuery", as_="fails")
    s("beginQuery", "ANY_SAMPLES_PASSED", R("passes"))
    draw(s)
    s("endQuery", "ANY_SAMPLES_PASSED")
    s("enable", "DEPTH_TEST")
    s("depthFunc", "NEVER")
    s("beginQuery", "ANY_SAMPLES_PASSED_CONSERVATIVE", R("fails"))
    draw(s)
    s("endQuery", "ANY_SAMPLES_PASSED_CONSERVATIVE")
    s("depthFunc", "LESS")
    s("disable", "DEPTH_TEST")
    s("getQueryParameter", R("passes"), "QUERY_RESULT_AVAILABLE", record="passes.availableAtOnce")
    s("finish")
    s("getQueryParameter", R("passes"), "QUERY_RESULT_AVAILABLE", record="passes.availableAfterFinish")
    s("getQueryParameter", R("passes"), "QUERY_RESULT_AVAILABLE", until=True)
    s("getQueryParameter", R("fails"), "QUERY_RESULT_AVAILABLE", until=True)
    s("getQueryParameter", R("passes"), "QUERY_RESULT", record="passes.result")
    s("getQueryParameter", R("fails"), "QUERY_RESULT", record="fails.result")


# ---------------------------------------------------------------- sync

@probe("sync-objects", "Fence syncs: getSyncParameter answers (OBJECT_TYPE, SYNC_CONDITION, SYNC_FLAGS), "
       "SYNC_STATUS becomes SIGNALED after returning to the event loop (`until`), then clientWaitSync is "
       "ALREADY_SIGNALED; errors: fenceSync with a bad condition (INVALID_ENUM) or flags (INVALID_VALUE), "
       "clientWaitSync with flags other than SYNC_FLUSH_COMMANDS_BIT (INVALID_VALUE) or a timeout over "
       "MAX_CLIENT_WAIT_TIMEOUT_WEBGL (INVALID_OPERATION), waitSync with a timeout other than TIMEOUT_IGNORED "
       "(INVALID_VALUE).")
def sync_objects(s):
    s("getParameter", "MAX_CLIENT_WAIT_TIMEOUT_WEBGL", record="MAX_CLIENT_WAIT_TIMEOUT_WEBGL")
    s("fenceSync", "SYNC_GPU_COMMANDS_COMPLETE", 0, as_="fence")
    s("isSync", R("fence"), record="isSync")
    for p in ("OBJECT_TYPE", "SYNC_CONDITION", "SYNC_FLAGS"):
        s("getSyncParameter", R("fence"), p, record=f"fence.{p}")
    s("getSyncParameter", R("fence"), "SYNC_STATUS", until="SIGNALED")
    s("clientWaitSync", R("fence"), 0, 0, record="clientWaitSync.signaled")
    s("fenceSync", "ALREADY_SIGNALED", 0, error="INVALID_ENUM", record="badCondition")
    s("fenceSync", "SYNC_GPU_COMMANDS_COMPLETE", 1, error="INVALID_VALUE", record="badFlags")
    s("clientWaitSync", R("fence"), 2, 0, error="INVALID_VALUE", record="clientWait.badFlags")
    s("clientWaitSync", R("fence"), 0, 1000000000000, error="INVALID_OPERATION", record="clientWait.longTimeout")
    s("waitSync", R("fence"), 0, 0, error="INVALID_VALUE")
    s("waitSync", R("fence"), 0, -1)
    s("getSyncParameter", R("fence"), "TEXTURE_2D", error="INVALID_ENUM", record="badPname")
    s("deleteSync", R("fence"))
    s("isSync", R("fence"), record="isSync.deleted")


# ---------------------------------------------------------------- transform feedback

def tf_setup(s, mode="INTERLEAVED_ATTRIBS", varyings=("v_vector", "v_scalar"), values=(1.0, 2.0, 3.0, 4.0)):
    program(s, "capture", "common-empty.frag", vert="probes/tf-capture.vert", varyings=list(varyings), mode=mode)
    s("createBuffer", as_="input")
    s("bindBuffer", "ARRAY_BUFFER", R("input"))
    s("bufferData", "ARRAY_BUFFER", F32(values), "STATIC_DRAW")
    s("enableVertexAttribArray", 0)
    s("vertexAttribPointer", 0, 1, "FLOAT", False, 0, 0)
    s("bindBuffer", "ARRAY_BUFFER", None)
    s("useProgram", R("capture"))
    s("createTransformFeedback", as_="tf")
    s("bindTransformFeedback", "TRANSFORM_FEEDBACK", R("tf"))


def tf_buffer(s, name, size, index=0):
    s("createBuffer", as_=name)
    s("bindBuffer", "TRANSFORM_FEEDBACK_BUFFER", R(name))
    s("bufferData", "TRANSFORM_FEEDBACK_BUFFER", size, "STATIC_READ")
    s("bindBufferBase", "TRANSFORM_FEEDBACK_BUFFER", index, R(name))


@probe("tf-capture", "Transform feedback captures exactly: 4 points through INTERLEAVED_ATTRIBS (a vec4 and a "
       "float, 20 bytes a vertex), read back with getBufferSubData; the indexed binding and "
       "TRANSFORM_FEEDBACK_ACTIVE/PAUSED answer, as does the primitives-written query.")
def tf_capture(s):
    tf_setup(s)
    tf_buffer(s, "out", 80)
    s("getIndexedParameter", "TRANSFORM_FEEDBACK_BUFFER_BINDING", 0, record="binding0")
    s("getIndexedParameter", "TRANSFORM_FEEDBACK_BUFFER_SIZE", 0, record="binding0.size")
    s("getParameter", "TRANSFORM_FEEDBACK_BINDING", record="TRANSFORM_FEEDBACK_BINDING")
    s("enable", "RASTERIZER_DISCARD")
    s("createQuery", as_="written")
    s("beginQuery", "TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN", R("written"))
    s("beginTransformFeedback", "POINTS")
    s("getParameter", "TRANSFORM_FEEDBACK_ACTIVE", record="active.whileActive")
    s("pauseTransformFeedback")
    s("getParameter", "TRANSFORM_FEEDBACK_PAUSED", record="paused.whilePaused")
    s("resumeTransformFeedback")
    s("drawArrays", "POINTS", 0, 4)
    s("endTransformFeedback")
    s("endQuery", "TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN")
    s("disable", "RASTERIZER_DISCARD")
    s("getParameter", "TRANSFORM_FEEDBACK_ACTIVE", record="active.afterEnd")
    s("bindTransformFeedback", "TRANSFORM_FEEDBACK", None)
    s("getParameter", "TRANSFORM_FEEDBACK_BINDING", record="TRANSFORM_FEEDBACK_BINDING.default")
    s("bindBuffer", "COPY_READ_BUFFER", R("out"))
    s("getBufferSubData", "COPY_READ_BUFFER", 0, OUT("f32", 20), record="captured")
    s("getQueryParameter", R("written"), "QUERY_RESULT_AVAILABLE", until=True)
    s("getQueryParameter", R("written"), "QUERY_RESULT", record="written")


@probe("tf-separate", "SEPARATE_ATTRIBS: each varying into its own buffer (binding 0 and 1); the same buffer at "
       "both bindings makes beginTransformFeedback INVALID_OPERATION (WebGL).")
def tf_separate(s):
    tf_setup(s, mode="SEPARATE_ATTRIBS")
    tf_buffer(s, "vectors", 64, 0)
    tf_buffer(s, "scalars", 16, 1)
    s("enable", "RASTERIZER_DISCARD")
    s("beginTransformFeedback", "POINTS")
    s("drawArrays", "POINTS", 0, 4)
    s("endTransformFeedback")
    s("bindBufferBase", "TRANSFORM_FEEDBACK_BUFFER", 1, R("vectors"))
    s("beginTransformFeedback", "POINTS", error="INVALID_OPERATION")
    s("getParameter", "TRANSFORM_FEEDBACK_ACTIVE", record="activeAfterFailedBegin")
    s("disable", "RASTERIZER_DISCARD")
    s("bindBuffer", "COPY_READ_BUFFER", R("scalars"))
    s("getBufferSubData", "COPY_READ_BUFFER", 0, OUT("f32", 4), record="scalars")


@probe("tf-failed-begin", "Chromium's state after a beginTransformFeedback that failed (the same buffer at "
       "two SEPARATE_ATTRIBS bindings): TRANSFORM_FEEDBACK_ACTIVE is false, yet bindTransformFeedback is "
       "INVALID_OPERATION (as if active) until an endTransformFeedback, itself INVALID_OPERATION, resets it. "
       "ES 3.0 would answer NO_ERROR to the bind; a Chromium quirk, kept apart from the other probes.")
def tf_failed_begin(s):
    tf_setup(s, mode="SEPARATE_ATTRIBS")
    tf_buffer(s, "vectors", 64, 0)
    s("bindBufferBase", "TRANSFORM_FEEDBACK_BUFFER", 1, R("vectors"))
    s("enable", "RASTERIZER_DISCARD")
    s("beginTransformFeedback", "POINTS", error="INVALID_OPERATION")
    s("getParameter", "TRANSFORM_FEEDBACK_ACTIVE", record="activeAfterFailedBegin")
    s("bindTransformFeedback", "TRANSFORM_FEEDBACK", None, error="INVALID_OPERATION")
    s("endTransformFeedback", error="INVALID_OPERATION")
    s("bindTransformFeedback", "TRANSFORM_FEEDBACK", None)
    s("disable", "RASTERIZER_DISCARD")


@probe("tf-primitive-mode", "While transform feedback is active with POINTS, drawing TRIANGLES or LINES is "
       "INVALID_OPERATION; beginTransformFeedback with TRIANGLE_STRIP is INVALID_ENUM; with TRIANGLES, "
       "drawing TRIANGLE_STRIP is INVALID_OPERATION (ES 3.0 allows only the matching base mode... recorded).")
def tf_primitive_mode(s):
    tf_setup(s)
    tf_buffer(s, "out", 400)
    s("enable", "RASTERIZER_DISCARD")
    s("beginTransformFeedback", "TRIANGLE_STRIP", error="INVALID_ENUM")
    s("beginTransformFeedback", "POINTS")
    s("drawArrays", "TRIANGLES", 0, 3, error="INVALID_OPERATION")
    s("drawArrays", "LINES", 0, 2, error="INVALID_OPERATION")
    s("drawArrays", "POINTS", 0, 1)
    s("endTransformFeedback")
    s("beginTransformFeedback", "TRIANGLES")
    s("drawArrays", "TRIANGLE_STRIP", 0, 3, error="INVALID_OPERATION")
    s("drawArrays", "TRIANGLES", 0, 3)
    s("endTransformFeedback")
    s("disable", "RASTERIZER_DISCARD")
    s("bindTransformFeedback", "TRANSFORM_FEEDBACK", None)


@probe("tf-buffer-too-small", "A transform feedback buffer with room for 3 of 4 vertices (60 of 80 bytes): "
       "drawing 4 points is INVALID_OPERATION and writes nothing; 3 points fit.")
def tf_buffer_too_small(s):
    tf_setup(s)
    tf_buffer(s, "out", 60)
    s("enable", "RASTERIZER_DISCARD")
    s("beginTransformFeedback", "POINTS")
    s("drawArrays", "POINTS", 0, 4, error="INVALID_OPERATION")
    s("drawArrays", "POINTS", 0, 3)
    s("drawArrays", "POINTS", 0, 1, error="INVALID_OPERATION")
    s("endTransformFeedback")
    s("disable", "RASTERIZER_DISCARD")
    s("bindTransformFeedback", "TRANSFORM_FEEDBACK", None)
    s("bindBuffer", "COPY_READ_BUFFER", R("out"))
    s("getBufferSubData", "COPY_READ_BUFFER", 0, OUT("f32", 15), record="captured")


@probe("tf-active-misuse", "While transform feedback is active: linkProgram of the active program, useProgram of "
       "another, bindBufferBase on TRANSFORM_FEEDBACK_BUFFER, bindTransformFeedback, a second "
       "and a second beginTransformFeedback are INVALID_OPERATION; paused, useProgram and "
       "bindTransformFeedback are allowed, but resumeTransformFeedback with another program in use is "
       "INVALID_OPERATION; endTransformFeedback, pause and resume out of order are INVALID_OPERATION.")
def tf_active_misuse(s):
    tf_setup(s)
    program(s, "other", "common-solid.frag")
    tf_buffer(s, "out", 80)
    s("createTransformFeedback", as_="tf2")
    s("endTransformFeedback", error="INVALID_OPERATION")
    s("pauseTransformFeedback", error="INVALID_OPERATION")
    s("resumeTransformFeedback", error="INVALID_OPERATION")
    s("beginTransformFeedback", "POINTS")
    s("beginTransformFeedback", "POINTS", error="INVALID_OPERATION")
    s("resumeTransformFeedback", error="INVALID_OPERATION")
    s("linkProgram", R("capture"), error="INVALID_OPERATION")
    s("useProgram", R("other"), error="INVALID_OPERATION")
    s("bindBufferBase", "TRANSFORM_FEEDBACK_BUFFER", 0, R("out"), error="INVALID_OPERATION")
    s("bindTransformFeedback", "TRANSFORM_FEEDBACK", R("tf2"), error="INVALID_OPERATION")
    s("pauseTransformFeedback")
    s("pauseTransformFeedback", error="INVALID_OPERATION")
    s("useProgram", R("other"))
    s("resumeTransformFeedback", error="INVALID_OPERATION")
    s("useProgram", R("capture"))
    s("bindTransformFeedback", "TRANSFORM_FEEDBACK", R("tf2"))
    s("bindTransformFeedback", "TRANSFORM_FEEDBACK", R("tf"))
    s("resumeTransformFeedback")
    s("endTransformFeedback")
    s("linkProgram", R("capture"))
    s("bindTransformFeedback", "TRANSFORM_FEEDBACK", None)


@probe("tf-begin-errors", "beginTransformFeedback errors: no program in use, a program without transform "
       "feedback varyings, or no buffer at a binding the program writes are INVALID_OPERATION; "
       "transformFeedbackVaryings with more SEPARATE_ATTRIBS than MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS is "
       "INVALID_VALUE; a varying name that is not an output fails the link.")
def tf_begin_errors(s):
    program(s, "plain", "common-solid.frag")
    s("createTransformFeedback", as_="tf")
    s("bindTransformFeedback", "TRANSFORM_FEEDBACK", R("tf"))
    s("beginTransformFeedback", "POINTS", error="INVALID_OPERATION")
    s("useProgram", R("plain"))
    s("beginTransformFeedback", "POINTS", error="INVALID_OPERATION")
    program(s, "capture", "common-empty.frag", vert="probes/tf-capture.vert", varyings=["v_vector", "v_scalar"])
    s("useProgram", R("capture"))
    s("beginTransformFeedback", "POINTS", error="INVALID_OPERATION")
    s("getParameter", "MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS", record="MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS")
    s("transformFeedbackVaryings", R("plain"), ["a", "b", "c", "d", "e"], "SEPARATE_ATTRIBS", error="INVALID_VALUE")
    s("createShader", "VERTEX_SHADER", as_="bad.vs")
    s("shaderSource", R("bad.vs"), {"file": "tf-capture.vert"})
    s("compileShader", R("bad.vs"))
    s("createProgram", as_="bad")
    s("attachShader", R("bad"), R("bad.vs"))
    s("attachShader", R("bad"), R("capture.fs"))
    s("transformFeedbackVaryings", R("bad"), ["v_vector", "v_missing"], "INTERLEAVED_ATTRIBS")
    s("linkProgram", R("bad"), status=False)
    s("bindTransformFeedback", "TRANSFORM_FEEDBACK", None)


@probe("tf-double-bound", "A buffer bound for transform feedback output and also as the source of a vertex "
       "attribute makes the draw INVALID_OPERATION (WebGL); so does a binding to the generic ARRAY_BUFFER "
       "point alone, with no attribute reading it (WebGL 2: 'any other binding point').")
def tf_double_bound(s):
    tf_setup(s)
    tf_buffer(s, "out", 80)
    s("bindBuffer", "TRANSFORM_FEEDBACK_BUFFER", None)
    s("enable", "RASTERIZER_DISCARD")
    s("bindBuffer", "ARRAY_BUFFER", R("out"))
    s("beginTransformFeedback", "POINTS")
    s("drawArrays", "POINTS", 0, 4, error="INVALID_OPERATION")
    s("endTransformFeedback")
    s("vertexAttribPointer", 0, 1, "FLOAT", False, 0, 0)
    s("beginTransformFeedback", "POINTS")
    s("drawArrays", "POINTS", 0, 4, error="INVALID_OPERATION")
    s("endTransformFeedback")
    s("disable", "RASTERIZER_DISCARD")
    s("bindBuffer", "ARRAY_BUFFER", None)
    s("bindTransformFeedback", "TRANSFORM_FEEDBACK", None)


# ---------------------------------------------------------------- getParameter

LIMITS_FB = ["MAX_DRAW_BUFFERS", "MAX_COLOR_ATTACHMENTS", "MAX_SAMPLES", "MAX_RENDERBUFFER_SIZE", "MAX_TEXTURE_SIZE",
             "MAX_CUBE_MAP_TEXTURE_SIZE", "MAX_3D_TEXTURE_SIZE", "MAX_ARRAY_TEXTURE_LAYERS", "MAX_VIEWPORT_DIMS",
             "SUBPIXEL_BITS", "SAMPLES", "SAMPLE_BUFFERS", "RED_BITS", "GREEN_BITS", "BLUE_BITS", "ALPHA_BITS",
             "DEPTH_BITS", "STENCIL_BITS", "IMPLEMENTATION_COLOR_READ_FORMAT", "IMPLEMENTATION_COLOR_READ_TYPE"]
LIMITS_OTHER = ["MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS", "MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS",
                "MAX_TRANSFORM_FEEDBACK_SEPARATE_COMPONENTS", "MAX_UNIFORM_BUFFER_BINDINGS", "MAX_UNIFORM_BLOCK_SIZE",
                "UNIFORM_BUFFER_OFFSET_ALIGNMENT", "MAX_VERTEX_UNIFORM_BLOCKS", "MAX_FRAGMENT_UNIFORM_BLOCKS",
                "MAX_COMBINED_UNIFORM_BLOCKS", "MAX_VERTEX_ATTRIBS", "MAX_VARYING_VECTORS", "MAX_VARYING_COMPONENTS",
                "MAX_VERTEX_OUTPUT_COMPONENTS", "MAX_FRAGMENT_INPUT_COMPONENTS", "MAX_VERTEX_UNIFORM_VECTORS",
                "MAX_FRAGMENT_UNIFORM_VECTORS", "MAX_VERTEX_UNIFORM_COMPONENTS", "MAX_FRAGMENT_UNIFORM_COMPONENTS",
                "MAX_COMBINED_VERTEX_UNIFORM_COMPONENTS", "MAX_COMBINED_FRAGMENT_UNIFORM_COMPONENTS",
                "MAX_TEXTURE_IMAGE_UNITS", "MAX_VERTEX_TEXTURE_IMAGE_UNITS", "MAX_COMBINED_TEXTURE_IMAGE_UNITS",
                "MAX_TEXTURE_LOD_BIAS", "MIN_PROGRAM_TEXEL_OFFSET", "MAX_PROGRAM_TEXEL_OFFSET", "MAX_ELEMENT_INDEX",
                "MAX_ELEMENTS_VERTICES", "MAX_ELEMENTS_INDICES", "MAX_SERVER_WAIT_TIMEOUT",
                "MAX_CLIENT_WAIT_TIMEOUT_WEBGL", "ALIASED_POINT_SIZE_RANGE", "ALIASED_LINE_WIDTH_RANGE"]


@probe("getparameter-limits-framebuffer", "getParameter for the framebuffer limits and the default framebuffer's "
       "bits (antialias: false, depth, no stencil); the limits depend on the GPU (here SwiftShader).")
def getparameter_limits_framebuffer(s):
    for name in LIMITS_FB:
        s("getParameter", name, record=name)


@probe("getparameter-limits-other", "getParameter for the transform feedback, uniform block, varying, texture "
       "unit, texel offset, element and sync limits; they depend on the GPU (here SwiftShader).")
def getparameter_limits_other(s):
    for name in LIMITS_OTHER:
        s("getParameter", name, record=name)


@probe("getparameter-bindings", "getParameter for the WebGL 2 bindings, initially and after binding: "
       "DRAW_FRAMEBUFFER_BINDING (= FRAMEBUFFER_BINDING), READ_FRAMEBUFFER_BINDING, RENDERBUFFER_BINDING, "
       "SAMPLER_BINDING, TRANSFORM_FEEDBACK_BINDING, the buffer bindings, VERTEX_ARRAY_BINDING, "
       "TEXTURE_BINDING_2D_ARRAY/3D, READ_BUFFER, DRAW_BUFFER0; getIndexedParameter for UNIFORM_BUFFER.")
def getparameter_bindings(s):
    names = ["DRAW_FRAMEBUFFER_BINDING", "FRAMEBUFFER_BINDING", "READ_FRAMEBUFFER_BINDING", "RENDERBUFFER_BINDING",
             "SAMPLER_BINDING", "TRANSFORM_FEEDBACK_BINDING", "TRANSFORM_FEEDBACK_BUFFER_BINDING",
             "UNIFORM_BUFFER_BINDING", "COPY_READ_BUFFER_BINDING", "COPY_WRITE_BUFFER_BINDING",
             "PIXEL_PACK_BUFFER_BINDING", "PIXEL_UNPACK_BUFFER_BINDING", "VERTEX_ARRAY_BINDING",
             "TEXTURE_BINDING_2D_ARRAY", "TEXTURE_BINDING_3D", "READ_BUFFER", "DRAW_BUFFER0",
             "TRANSFORM_FEEDBACK_ACTIVE", "TRANSFORM_FEEDBACK_PAUSED", "RASTERIZER_DISCARD"]
    for name in names:
        s("getParameter", name, record=f"initial.{name}")
    s("createFramebuffer", as_="drawFb")
    s("createFramebuffer", as_="readFb")
    s("bindFramebuffer", "DRAW_FRAMEBUFFER", R("drawFb"))
    s("bindFramebuffer", "READ_FRAMEBUFFER", R("readFb"))
    for name in ("DRAW_FRAMEBUFFER_BINDING", "FRAMEBUFFER_BINDING", "READ_FRAMEBUFFER_BINDING"):
        s("getParameter", name, record=f"separate.{name}")
    s("bindFramebuffer", "FRAMEBUFFER", R("drawFb"))
    s("getParameter", "READ_FRAMEBUFFER_BINDING", record="bothToDraw.READ_FRAMEBUFFER_BINDING")
    s("bindFramebuffer", "FRAMEBUFFER", None)
    s("createBuffer", as_="ubo")
    s("bindBuffer", "UNIFORM_BUFFER", R("ubo"))
    s("bufferData", "UNIFORM_BUFFER", 512, "STATIC_DRAW")
    s("bindBufferRange", "UNIFORM_BUFFER", 2, R("ubo"), 256, 128)
    for name in ("UNIFORM_BUFFER_BINDING", "UNIFORM_BUFFER_START", "UNIFORM_BUFFER_SIZE"):
        s("getIndexedParameter", name, 2, record=f"indexed2.{name}")
    s("getIndexedParameter", "UNIFORM_BUFFER_BINDING", 1, record="indexed1.UNIFORM_BUFFER_BINDING")
    s("getIndexedParameter", "UNIFORM_BUFFER_BINDING", 1000, error="INVALID_VALUE", record="indexedTooHigh")
    s("bindBufferRange", "UNIFORM_BUFFER", 3, R("ubo"), 10, 16, error="INVALID_VALUE")
    s("createTransformFeedback", as_="tf")
    s("bindTransformFeedback", "TRANSFORM_FEEDBACK", R("tf"))
    s("getParameter", "TRANSFORM_FEEDBACK_BINDING", record="bound.TRANSFORM_FEEDBACK_BINDING")
    s("bindTransformFeedback", "TRANSFORM_FEEDBACK", None)


@probe("shader-precision-formats", "getShaderPrecisionFormat for both shader types and the six precisions "
       "(rangeMin, rangeMax, precision); GPU-dependent.")
def shader_precision_formats(s):
    for stage in ("VERTEX_SHADER", "FRAGMENT_SHADER"):
        for kind in ("LOW_FLOAT", "MEDIUM_FLOAT", "HIGH_FLOAT", "LOW_INT", "MEDIUM_INT", "HIGH_INT"):
            s("getShaderPrecisionFormat", stage, kind, record=f"{stage}.{kind}")
    s("getShaderPrecisionFormat", "VERTEX_SHADER", "FLOAT", error="INVALID_ENUM", record="badType")


@probe("context-attributes-default", "getContextAttributes for a context asked for with WebGL's defaults (the "
       "script gives no context attributes: antialias true, depth true, stencil false, alpha true, "
       "premultipliedAlpha true, preserveDrawingBuffer false), and the default framebuffer's SAMPLES.")
def context_attributes_default(s):
    s("getContextAttributes", record="attributes")
    s("getParameter", "SAMPLES", record="SAMPLES")
    s("getParameter", "DEPTH_BITS", record="DEPTH_BITS")
    s("getParameter", "STENCIL_BITS", record="STENCIL_BITS")


@probe("context-attributes-stencil", "getContextAttributes for antialias: false, stencil: true, alpha: false.",
       context={"stencil": True, "alpha": False})
def context_attributes_stencil(s):
    s("getContextAttributes", record="attributes")
    s("getParameter", "ALPHA_BITS", record="ALPHA_BITS")
    s("getParameter", "STENCIL_BITS", record="STENCIL_BITS")


@probe("supported-extensions", "getSupportedExtensions: the list depends on the GPU and the browser version.")
def supported_extensions(s):
    s("getSupportedExtensions", record="extensions")


# ---------------------------------------------------------------- textures and buffers around framebuffers

@probe("invalidate-framebuffer", "invalidateFramebuffer / invalidateSubFramebuffer: colour and depth attachments of "
       "a framebuffer are accepted; BACK or COLOR on a framebuffer object is INVALID_ENUM (or OPERATION? "
       "recorded); on the default framebuffer COLOR, DEPTH, STENCIL are accepted and COLOR_ATTACHMENT0 is "
       "INVALID_ENUM; a bad target is INVALID_ENUM. Contents afterwards are undefined; not read.")
def invalidate_framebuffer(s):
    s.texture("color", "TEXTURE_2D", "RGBA8", 4, 4)
    s.renderbuffer("depth", "DEPTH_COMPONENT16", 4, 4)
    s.framebuffer("fb", [("COLOR_ATTACHMENT0", "color", "TEXTURE_2D"), ("DEPTH_ATTACHMENT", "depth", "renderbuffer")])
    s("invalidateFramebuffer", "FRAMEBUFFER", ["COLOR_ATTACHMENT0", "DEPTH_ATTACHMENT"])
    s("invalidateSubFramebuffer", "DRAW_FRAMEBUFFER", ["COLOR_ATTACHMENT0"], 0, 0, 2, 2)
    s("invalidateFramebuffer", "FRAMEBUFFER", ["COLOR_ATTACHMENT5"])
    s("invalidateFramebuffer", "FRAMEBUFFER", ["BACK"], error="INVALID_ENUM")
    s("invalidateFramebuffer", "FRAMEBUFFER", ["COLOR"], error="INVALID_ENUM")
    s("invalidateFramebuffer", "FRAMEBUFFER", ["COLOR_ATTACHMENT15"], error="INVALID_OPERATION")
    s("bindFramebuffer", "FRAMEBUFFER", None)
    s("invalidateFramebuffer", "FRAMEBUFFER", ["COLOR", "DEPTH", "STENCIL"])
    s("invalidateFramebuffer", "FRAMEBUFFER", ["COLOR_ATTACHMENT0"], error="INVALID_ENUM")
    s("invalidateFramebuffer", "TEXTURE_2D", ["COLOR"], error="INVALID_ENUM")


@probe("copyteximage-formats", "copyTexImage2D from an RGBA8 framebuffer: RGBA8, RGB8, RGBA, LUMINANCE and R8 "
       "destinations are allowed (components may be dropped); RGB565 (different sizes) and RGBA8UI "
       "(another kind) are INVALID_OPERATION, R32F is INVALID_ENUM; from an RGB8 framebuffer, an RGBA "
       "destination (adding alpha) "
       "is INVALID_OPERATION.")
def copyteximage_formats(s):
    color_fb(s, "rgba8Fb", "RGBA8")
    s("clearColor", 0.2, 0.4, 0.6, 0.8)
    s("clear", "COLOR_BUFFER_BIT")
    s("createTexture", as_="dst")
    s("bindTexture", "TEXTURE_2D", R("dst"))
    for internal, error in (("RGBA8", None), ("RGB8", None), ("RGBA", None), ("LUMINANCE", None), ("R8", None),
                            ("RGB565", "INVALID_OPERATION"), ("R32F", "INVALID_ENUM"),
                            ("RGBA8UI", "INVALID_OPERATION")):
        s("copyTexImage2D", "TEXTURE_2D", 0, internal, 0, 0, 2, 2, 0, error=error)
    color_fb(s, "rgb8Fb", "RGB8")
    s("bindTexture", "TEXTURE_2D", R("dst"))
    s("copyTexImage2D", "TEXTURE_2D", 0, "RGBA", 0, 0, 2, 2, 0, error="INVALID_OPERATION")
    s("copyTexImage2D", "TEXTURE_2D", 0, "RGB8", 0, 0, 2, 2, 0)
    s("bindFramebuffer", "FRAMEBUFFER", None)


@probe("depth-texture-uploads", "Depth textures: texImage2D DEPTH_COMPONENT16 with UNSIGNED_SHORT data is allowed "
       "in WebGL 2; DEPTH32F_STENCIL8 with FLOAT_32_UNSIGNED_INT_24_8_REV and data is INVALID_OPERATION, as the "
       "spec says; texSubImage2D with that type is INVALID_OPERATION too (the spec says INVALID_ENUM); "
       "generateMipmap on a depth texture is INVALID_OPERATION.")
def depth_texture_uploads(s):
    s("createTexture", as_="d16")
    s("bindTexture", "TEXTURE_2D", R("d16"))
    s("texImage2D", "TEXTURE_2D", 0, "DEPTH_COMPONENT16", 2, 2, 0, "DEPTH_COMPONENT", "UNSIGNED_SHORT",
      U16([0, 16384, 32768, 65535]))
    s("generateMipmap", "TEXTURE_2D", error="INVALID_OPERATION")
    s("createTexture", as_="d32fs8")
    s("bindTexture", "TEXTURE_2D", R("d32fs8"))
    s("texImage2D", "TEXTURE_2D", 0, "DEPTH32F_STENCIL8", 1, 1, 0, "DEPTH_STENCIL", "FLOAT_32_UNSIGNED_INT_24_8_REV",
      {"u32": [0, 0]}, error="INVALID_OPERATION")
    s("texImage2D", "TEXTURE_2D", 0, "DEPTH32F_STENCIL8", 1, 1, 0, "DEPTH_STENCIL", "FLOAT_32_UNSIGNED_INT_24_8_REV",
      None)
    s("texSubImage2D", "TEXTURE_2D", 0, 0, 0, 1, 1, "DEPTH_STENCIL", "FLOAT_32_UNSIGNED_INT_24_8_REV",
      {"u32": [0, 0]}, error="INVALID_OPERATION")


@probe("texture-storage-immutable", "Immutable textures (texStorage2D): TEXTURE_IMMUTABLE_FORMAT and _LEVELS "
       "answer; texStorage2D again, or texImage2D on it, is INVALID_OPERATION; too many levels for the size is "
       "INVALID_OPERATION; an unsized format INVALID_ENUM; texSubImage2D of a level past the storage "
       "INVALID_OPERATION.")
def texture_storage_immutable(s):
    s("createTexture", as_="tex")
    s("bindTexture", "TEXTURE_2D", R("tex"))
    s("getTexParameter", "TEXTURE_2D", "TEXTURE_IMMUTABLE_FORMAT", record="before.IMMUTABLE_FORMAT")
    s("texStorage2D", "TEXTURE_2D", 5, "RGBA8", 4, 4, error="INVALID_OPERATION")
    s("texStorage2D", "TEXTURE_2D", 3, "RGBA", 4, 4, error="INVALID_ENUM")
    s("texStorage2D", "TEXTURE_2D", 3, "RGBA8", 4, 4)
    s("getTexParameter", "TEXTURE_2D", "TEXTURE_IMMUTABLE_FORMAT", record="after.IMMUTABLE_FORMAT")
    s("getTexParameter", "TEXTURE_2D", "TEXTURE_IMMUTABLE_LEVELS", record="after.IMMUTABLE_LEVELS")
    s("texStorage2D", "TEXTURE_2D", 1, "RGBA8", 4, 4, error="INVALID_OPERATION")
    s("texImage2D", "TEXTURE_2D", 0, "RGBA8", 4, 4, 0, "RGBA", "UNSIGNED_BYTE", None, error="INVALID_OPERATION")
    s("texSubImage2D", "TEXTURE_2D", 2, 0, 0, 1, 1, "RGBA", "UNSIGNED_BYTE", {"u8": [1, 2, 3, 4]})
    s("texSubImage2D", "TEXTURE_2D", 3, 0, 0, 1, 1, "RGBA", "UNSIGNED_BYTE", {"u8": [1, 2, 3, 4]},
      error="INVALID_OPERATION")


@probe("vertex-attrib-type-mismatch", "The attribute's type must fit the shader's: a uvec4 attribute fed by "
       "vertexAttribPointer (float) or vertexAttribIPointer(INT) is INVALID_OPERATION at the draw; "
       "vertexAttribIPointer(UNSIGNED_BYTE) draws; a vec2 attribute fed by vertexAttribIPointer is "
       "INVALID_OPERATION; a disabled attribute's current value type (vertexAttribI4ui) counts too.")
def vertex_attrib_type_mismatch(s):
    program(s, "uintAttr", "probes/attrib-uint.frag", vert="probes/attrib-uint.vert")
    program(s, "floatAttr", "common-solid.frag", vert="probes/attrib-float.vert")
    s("createBuffer", as_="data")
    s("bindBuffer", "ARRAY_BUFFER", R("data"))
    s("bufferData", "ARRAY_BUFFER", {"u8": [200] * 48}, "STATIC_DRAW")
    s("useProgram", R("uintAttr"))
    s("enableVertexAttribArray", 0)
    s("vertexAttribPointer", 0, 4, "UNSIGNED_BYTE", False, 0, 0)
    draw(s, error="INVALID_OPERATION")
    s("vertexAttribIPointer", 0, 4, "BYTE", 0, 0)
    draw(s, error="INVALID_OPERATION")
    s("vertexAttribIPointer", 0, 4, "UNSIGNED_BYTE", 0, 0)
    draw(s)
    s("disableVertexAttribArray", 0)
    s("vertexAttrib4f", 0, 1, 2, 3, 4)
    draw(s, error="INVALID_OPERATION")
    s("vertexAttribI4ui", 0, 60, 0, 0, 0)
    draw(s)
    s("useProgram", R("floatAttr"))
    draw(s, error="INVALID_OPERATION")
    s("enableVertexAttribArray", 0)
    s("vertexAttribIPointer", 0, 2, "SHORT", 0, 0)
    draw(s, error="INVALID_OPERATION")
    s("disableVertexAttribArray", 0)
    s("bindBuffer", "ARRAY_BUFFER", None)


@probe("uniform-block-too-small", "A uniform block of 32 bytes backed by a 16-byte buffer range, or by nothing, "
       "makes drawArrays INVALID_OPERATION (WebGL); a 32-byte range at a 256-byte offset draws.")
def uniform_block_too_small(s):
    program(s, "block", "probes/block.frag")
    s("getUniformBlockIndex", R("block"), "Colors", as_="colors")
    s("getActiveUniformBlockParameter", R("block"), R("colors"), "UNIFORM_BLOCK_DATA_SIZE", record="dataSize")
    s("uniformBlockBinding", R("block"), R("colors"), 1)
    s("useProgram", R("block"))
    draw(s, error="INVALID_OPERATION")
    s("getParameter", "UNIFORM_BUFFER_OFFSET_ALIGNMENT", record="UNIFORM_BUFFER_OFFSET_ALIGNMENT")
    s("createBuffer", as_="ubo")
    s("bindBuffer", "UNIFORM_BUFFER", R("ubo"))
    first, second = [0.4, 0.2, 0.1, 0.5], [0.2, 0.25, 0.25, 0.5]  # sums: no channel on a half of 1/255
    s("bufferData", "UNIFORM_BUFFER", F32([0.1, 0.2, 0.3, 0.5] * 2 + [0] * 56 + first + second), "STATIC_DRAW")
    s("bindBufferRange", "UNIFORM_BUFFER", 1, R("ubo"), 0, 16)
    draw(s, error="INVALID_OPERATION")
    s("bindBufferRange", "UNIFORM_BUFFER", 1, R("ubo"), 256, 32)
    draw(s)
    read(s, "drawn")


@probe("buffer-type-rules", "WebGL's buffer kinds: a buffer first bound to ELEMENT_ARRAY_BUFFER cannot be bound "
       "to ARRAY_BUFFER or TRANSFORM_FEEDBACK_BUFFER, nor copied to or from another kind (INVALID_OPERATION); "
       "getBufferSubData past the end is INVALID_VALUE; copyBufferSubData within one buffer with overlapping "
       "ranges INVALID_VALUE.")
def buffer_type_rules(s):
    s("createBuffer", as_="index")
    s("bindBuffer", "ELEMENT_ARRAY_BUFFER", R("index"))
    s("bufferData", "ELEMENT_ARRAY_BUFFER", U16([0, 1, 2, 3]), "STATIC_DRAW")
    s("bindBuffer", "ARRAY_BUFFER", R("index"), error="INVALID_OPERATION")
    s("bindBufferBase", "TRANSFORM_FEEDBACK_BUFFER", 0, R("index"), error="INVALID_OPERATION")
    s("bindBuffer", "COPY_READ_BUFFER", R("index"))
    s("createBuffer", as_="data")
    s("bindBuffer", "COPY_WRITE_BUFFER", R("data"))
    s("bufferData", "COPY_WRITE_BUFFER", 16, "STATIC_DRAW")
    s("copyBufferSubData", "COPY_READ_BUFFER", "COPY_WRITE_BUFFER", 0, 0, 8, error="INVALID_OPERATION")
    s("bindBuffer", "ELEMENT_ARRAY_BUFFER", R("data"), error="INVALID_OPERATION")
    s("getBufferSubData", "COPY_READ_BUFFER", 4, OUT("u16", 4), error="INVALID_VALUE")
    s("getBufferSubData", "COPY_READ_BUFFER", 2, OUT("u16", 3), record="indexBytes2to8")
    s("bufferSubData", "COPY_WRITE_BUFFER", 0, F32([1, 2, 3, 4]))
    s("copyBufferSubData", "COPY_WRITE_BUFFER", "COPY_WRITE_BUFFER", 0, 4, 8, error="INVALID_VALUE")
    s("copyBufferSubData", "COPY_WRITE_BUFFER", "COPY_WRITE_BUFFER", 0, 8, 8)
    s("getBufferSubData", "COPY_WRITE_BUFFER", 0, OUT("f32", 4), record="afterCopy")


@probe("msaa-default-framebuffer", "An antialiased canvas (antialias: true): SAMPLES and SAMPLE_BUFFERS of the "
       "default framebuffer, readPixels resolves; blitting from it into a texture framebuffer of the same size "
       "resolves; a scaled blit from it is INVALID_OPERATION.", context={"antialias": True})
def msaa_default_framebuffer(s):
    solid(s, color=(1.0, 0.6, 0.0, 1.0))
    s("getParameter", "SAMPLES", record="SAMPLES")
    s("getParameter", "SAMPLE_BUFFERS", record="SAMPLE_BUFFERS")
    s("clearColor", 0, 0, 0, 1)
    s("clear", "COLOR_BUFFER_BIT")
    draw(s)
    read(s, "default.pixel")
    color_fb(s, "dst", "RGBA8", 16)
    s("bindFramebuffer", "READ_FRAMEBUFFER", None)
    blit(s, src=(0, 0, 16, 16), dst=(0, 0, 16, 16))
    blit(s, src=(0, 0, 16, 16), dst=(0, 0, 8, 8), error="INVALID_OPERATION")
    s("bindFramebuffer", "READ_FRAMEBUFFER", R("dst"))
    read(s, "blitted.pixel", 3, 3)
    s("bindFramebuffer", "FRAMEBUFFER", None)


def write_all(folder):
    names = set()
    for name, description, fn, width, height, kw in PROBES:
        assert name not in names, name
        names.add(name)
        s = Script(name, description, width, height, **kw)
        if name == "context-attributes-default":
            s.context = {}
        fn(s)
        with open(os.path.join(folder, name + ".json"), "w", encoding="utf-8") as fh:
            fh.write(s.json(folder))
