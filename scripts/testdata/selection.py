"""Which upstream files the corpora leave out.

The shared corpora hold some upstream files back (kept aside for evaluation), so a
regenerated corpus matches them only when the same files are left out. Pass
`--include-held-back` to the extractor to keep everything instead.
"""

# dEQP: sdk/tests/deqp/data/gles3/shaders/*.test files not in deqp_gles3.jsonl.
DEQP_HELD_BACK = frozenset([
    'constant_expressions.test',
    'conversions_vector_illegal.test',
    'negative.test',
    'qualification_order.test',
    'scoping.test',
    'switch.test',
    'swizzles_ivec3.test',
])

# webgl2fundamentals: webgl/*.html pages not copied into webgl2fundamentals-pages/
# (their shaders are still in webgl2fundamentals_shaders.jsonl).
PAGES_HELD_BACK = frozenset([
    'webgl-2d-geometry-matrix-transform-simpler-functions.html',
    'webgl-2d-geometry-rotation.html',
    'webgl-2d-image-3x3-convolution.html',
    'webgl-2d-image-blend.html',
    'webgl-2d-image-processing.html',
    'webgl-2d-matrixstack-02.html',
    'webgl-2d-matrixstack-04.html',
    'webgl-2d-rectangles-indexed.html',
    'webgl-2d-triangle-with-position-for-color.html',
    'webgl-3d-camera-look-at.html',
    'webgl-3d-lighting-point-specular-power.html',
    'webgl-3d-step4.html',
    'webgl-gpgpu-closest-line-transformfeedback.html',
    'webgl-gpgpu-particles.html',
    'webgl-less-code-more-fun-triangle.html',
    'webgl-qna-apply-a-displacement-map-and-specular-map-example-1.html',
    'webgl-qna-drawing-textured-sprites-with-instanced-drawing-example-1.html',
    'webgl-qna-how-to-blend-colors-across-2-triangles-example-1.html',
    'webgl-qna-how-to-get-audio-data-into-a-shader-example-1.html',
    'webgl-qna-how-to-get-pixelize-effect-in-webgl--example-3.html',
    'webgl-qna-how-to-import-a-heightmap-in-webgl-example-3.html',
    'webgl-render-to-texture.html',
    'webgl-same-code-resize.html',
    'webgl-shadertoy-w-mouse.html',
    'webgl-shadows-w-directional-light.html',
    'webgl-skinning-3d-gltf-skinned.html',
    'webgl-skinning.html',
    'webgl-skybox-plus-environment-map.html',
    'webgl-tips-screenshot-bad.html',
    'webgl-tips-screenshot-good.html',
])

# WebGL conformance: pages (sdk/tests paths) whose cases are in neither
# webgl_conformance_es300.jsonl nor webgl_conformance_es100.jsonl.
WEBGL_HELD_BACK = frozenset([
    'conformance/glsl/bugs/compound-assignment-type-combination.html',
    'conformance/glsl/bugs/essl3-shaders-with-webgl1.html',
    'conformance/glsl/bugs/nested-functions-should-not-crash.html',
    'conformance/glsl/bugs/struct-constructor-highp-bug.html',
    'conformance/glsl/bugs/unary-minus-operator-float-bug.html',
    'conformance/glsl/constructors/glsl-construct-vec2.html',
    'conformance/glsl/implicit/add_int_mat2.vert.html',
    'conformance/glsl/implicit/add_int_vec2.vert.html',
    'conformance/glsl/implicit/equal_ivec2_vec2.vert.html',
    'conformance/glsl/implicit/subtract_int_mat3.vert.html',
    'conformance/glsl/implicit/subtract_int_vec3.vert.html',
    'conformance/glsl/literals/float_literal.vert.html',
    'conformance/glsl/misc/shader-uniform-packing-restrictions.html',
    'conformance/glsl/misc/shader-with-comma-assignment.html',
    'conformance/glsl/misc/shader-with-default-precision.frag.html',
    'conformance/glsl/misc/shader-with-do-loop.html',
    'conformance/glsl/misc/shader-with-include.vert.html',
    'conformance/glsl/misc/shader-with-vec4-vec3-vec4-conditional.html',
    'conformance/glsl/misc/shader-with-version-100.vert.html',
    'conformance/glsl/misc/shader-without-precision.frag.html',
    'conformance/glsl/misc/struct-nesting-exceeds-maximum.html',
    'conformance/glsl/misc/ternary-operators-in-initializers.html',
    'conformance/glsl/reserved/_webgl_field.vert.html',
    'conformance2/glsl3/compound-assignment-type-combination.html',
    'conformance2/glsl3/shader-with-1024-character-identifier.frag.html',
    'conformance2/glsl3/shader-with-1025-character-define.html',
    'extra/constant-index-out-of-range.html',
])
