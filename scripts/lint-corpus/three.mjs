// Assembles whole WebGL2 shaders from three.js's shader chunks, the way three.js's WebGLProgram
// does for its built-in materials: `#version 300 es`, the GLSL 3 conversion defines, the
// precision block, the material's and the renderer's defines, the built-in uniforms and
// attributes, then the material's source with `#include <chunk>` resolved, the light counts
// substituted and `#pragma unroll_loop_start` loops unrolled.
//
// Each material is written in a few configurations (lights of every kind, shadows, maps, fog,
// tone mapping), so that every lighting chunk is in some shader. Identical texts are written
// once.
//
// Usage: node three.mjs THREE_PACKAGE_DIR OUT_DIR
// (THREE_PACKAGE_DIR: the unpacked npm package, `npm pack three@0.170.0`).

import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const [pkg, out] = process.argv.slice(2);
if (!pkg || !out) {
	console.error('usage: node three.mjs THREE_PACKAGE_DIR OUT_DIR');
	process.exit(2);
}
const src = path.join(pkg, 'src/renderers/shaders');
const { ShaderChunk } = await import(pathToFileURL(path.join(src, 'ShaderChunk.js')));
const { ShaderLib } = await import(pathToFileURL(path.join(src, 'ShaderLib.js')));

function resolveIncludes(s) {
	return s.replace(/^[ \t]*#include +<([\w\d./]+)>/gm, (_, name) => {
		if (ShaderChunk[name] === undefined) throw new Error(`no chunk ${name}`);
		return resolveIncludes(ShaderChunk[name]);
	});
}

function unrollLoops(s) {
	const pattern = /#pragma unroll_loop_start\s+for\s*\(\s*int\s+i\s*=\s*(\d+)\s*;\s*i\s*<\s*(\d+)\s*;\s*i\s*\+\+\s*\)\s*{([\s\S]+?)}\s+#pragma unroll_loop_end/g;
	return s.replace(pattern, (_, start, end, body) => {
		let r = '';
		for (let i = +start; i < +end; i++) {
			r += body.replace(/\[\s*i\s*\]/g, `[ ${i} ]`).replace(/UNROLLED_LOOP_INDEX/g, i);
		}
		return r;
	});
}

function replaceNums(s, p) {
	const spotCoords = p.spotShadows;
	return s
		.replace(/NUM_DIR_LIGHTS/g, p.dir)
		.replace(/NUM_SPOT_LIGHTS/g, p.spot)
		.replace(/NUM_SPOT_LIGHT_MAPS/g, 0)
		.replace(/NUM_SPOT_LIGHT_COORDS/g, spotCoords)
		.replace(/NUM_RECT_AREA_LIGHTS/g, p.rect)
		.replace(/NUM_POINT_LIGHTS/g, p.point)
		.replace(/NUM_HEMI_LIGHTS/g, p.hemi)
		.replace(/NUM_DIR_LIGHT_SHADOWS/g, p.dirShadows)
		.replace(/NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS/g, 0)
		.replace(/NUM_SPOT_LIGHT_SHADOWS/g, p.spotShadows)
		.replace(/NUM_POINT_LIGHT_SHADOWS/g, p.pointShadows)
		.replace(/NUM_CLIPPING_PLANES/g, 0)
		.replace(/UNION_CLIPPING_PLANES/g, 0);
}

const precision = `precision highp float;
precision highp int;
precision highp sampler2D;
precision highp samplerCube;
precision highp sampler3D;
precision highp sampler2DArray;
precision highp sampler2DShadow;
precision highp samplerCubeShadow;
precision highp sampler2DArrayShadow;
precision highp isampler2D;
precision highp isampler3D;
precision highp isamplerCube;
precision highp isampler2DArray;
precision highp usampler2D;
precision highp usampler3D;
precision highp usamplerCube;
precision highp usampler2DArray;
#define HIGH_PRECISION`;

const vertexHeader = `uniform mat4 modelMatrix;
uniform mat4 modelViewMatrix;
uniform mat4 projectionMatrix;
uniform mat4 viewMatrix;
uniform mat3 normalMatrix;
uniform vec3 cameraPosition;
uniform bool isOrthographic;
#ifdef USE_INSTANCING
	attribute mat4 instanceMatrix;
#endif
#ifdef USE_INSTANCING_COLOR
	attribute vec3 instanceColor;
#endif
attribute vec3 position;
attribute vec3 normal;
attribute vec2 uv;
#ifdef USE_TANGENT
	attribute vec4 tangent;
#endif
#if defined( USE_COLOR_ALPHA )
	attribute vec4 color;
#elif defined( USE_COLOR )
	attribute vec3 color;
#endif
#ifdef USE_SKINNING
	attribute vec4 skinIndex;
	attribute vec4 skinWeight;
#endif
`;

const toneMappings = { aces: 'ACESFilmic', agx: 'AgX', neutral: 'Neutral', reinhard: 'Reinhard', cineon: 'Cineon' };

// The renderer's defines for one configuration (`c`), vertex and fragment.
function prefix(c, stage, materialDefines, shaderName) {
	const on = (flag, line) => (flag ? line : '');
	const maps = c.maps
		? ['#define USE_MAP', '#define MAP_UV uv', '#define USE_NORMALMAP', '#define USE_NORMALMAP_TANGENTSPACE',
			'#define NORMALMAP_UV uv', '#define USE_ROUGHNESSMAP', '#define ROUGHNESSMAP_UV uv',
			'#define USE_METALNESSMAP', '#define METALNESSMAP_UV uv', '#define USE_EMISSIVEMAP', '#define EMISSIVEMAP_UV uv',
			'#define USE_AOMAP', '#define AOMAP_UV uv', '#define USE_BUMPMAP', '#define BUMPMAP_UV uv',
			'#define USE_ALPHAMAP', '#define ALPHAMAP_UV uv', '#define USE_SPECULARMAP', '#define SPECULARMAP_UV uv',
			'#define USE_LIGHTMAP', '#define LIGHTMAP_UV uv']
		: [];
	const env = c.env
		? ['#define USE_ENVMAP', `#define ${c.env === 'cubeuv' ? 'ENVMAP_TYPE_CUBE_UV' : 'ENVMAP_TYPE_CUBE'}`,
			'#define ENVMAP_MODE_REFLECTION', '#define ENVMAP_BLENDING_MULTIPLY',
			...(c.env === 'cubeuv' ? ['#define CUBEUV_TEXEL_WIDTH 0.0013', '#define CUBEUV_TEXEL_HEIGHT 0.0006', '#define CUBEUV_MAX_MIP 8.0'] : [])]
		: [];
	const physical = c.physical
		? ['#define USE_CLEARCOAT', '#define USE_IRIDESCENCE', '#define USE_SHEEN', '#define USE_TRANSMISSION',
			'#define USE_ANISOTROPY', '#define USE_DISPERSION']
		: [];
	const lines = [
		precision,
		`#define SHADER_TYPE ${shaderName}`,
		`#define SHADER_NAME ${shaderName}`,
		...Object.entries(materialDefines).map(([k, v]) => `#define ${k} ${v}`),
		on(c.fog, '#define USE_FOG'), on(c.fog === 'exp2', '#define FOG_EXP2'),
		...maps, ...env, ...(stage === 'fragment' ? physical : []),
		on(c.maps, '#define USE_TANGENT'), on(c.color, '#define USE_COLOR'),
		on(c.skinning && stage === 'vertex', '#define USE_SKINNING'),
		on(c.instancing && stage === 'vertex', '#define USE_INSTANCING'),
		on(c.flat, '#define FLAT_SHADED'), on(c.doubleSided, '#define DOUBLE_SIDED'),
		on(c.shadows, '#define USE_SHADOWMAP'), on(c.shadows, `#define ${c.shadows}`),
		on(c.logdepth, '#define USE_LOGDEPTHBUF'),
		on(c.dithering && stage === 'fragment', '#define DITHERING'),
	];
	if (stage === 'vertex') {
		return ['#version 300 es', '#define attribute in', '#define varying out', '#define texture2D texture',
			...lines, vertexHeader].filter((l) => l !== '').join('\n') + '\n';
	}
	const tone = c.tone
		? ['#define TONE_MAPPING', ShaderChunk.tonemapping_pars_fragment,
			`vec3 toneMapping( vec3 color ) { return ${toneMappings[c.tone]}ToneMapping( color ); }`]
		: [];
	return ['#version 300 es', '#define varying in', 'layout(location = 0) out highp vec4 pc_fragColor;',
		'#define gl_FragColor pc_fragColor', '#define gl_FragDepthEXT gl_FragDepth', '#define texture2D texture',
		'#define textureCube texture', '#define texture2DProj textureProj', '#define texture2DLodEXT textureLod',
		'#define texture2DProjLodEXT textureProjLod', '#define textureCubeLodEXT textureLod',
		'#define texture2DGradEXT textureGrad', '#define texture2DProjGradEXT textureProjGrad',
		'#define textureCubeGradEXT textureGrad',
		...lines, 'uniform mat4 viewMatrix;', 'uniform vec3 cameraPosition;', 'uniform bool isOrthographic;',
		...tone, ShaderChunk.colorspace_pars_fragment,
		'vec4 linearToOutputTexel( vec4 value ) {\n\treturn sRGBTransferOETF( vec4( value.rgb * mat3( 1.0000, 0.0000, 0.0000, 0.0000, 1.0000, 0.0000, 0.0000, 0.0000, 1.0000 ), value.a ) );\n}',
		'float luminance( const in vec3 rgb ) {\n\tconst vec3 weights = vec3( 0.2126, 0.7152, 0.0722 );\n\treturn dot( weights, rgb );\n}',
	].filter((l) => l !== '').join('\n') + '\n';
}

const lights = { dir: 1, point: 1, spot: 1, rect: 0, hemi: 1, dirShadows: 0, spotShadows: 0, pointShadows: 0 };
const shadowed = { ...lights, dirShadows: 1, spotShadows: 1, pointShadows: 1 };
const configurations = {
	plain: { lights },
	maps: { lights, maps: true, fog: 'linear', tone: 'aces', color: true },
	shadows: { lights: shadowed, shadows: 'SHADOWMAP_TYPE_PCF_SOFT', fog: 'exp2', tone: 'agx', dithering: true },
	env: { lights: { ...lights, rect: 1 }, env: 'cubeuv', physical: true, tone: 'neutral', skinning: true, doubleSided: true },
	vsm: { lights: shadowed, shadows: 'SHADOWMAP_TYPE_VSM', env: 'cube', tone: 'reinhard', instancing: true, flat: true, logdepth: true },
	pcf: { lights: shadowed, shadows: 'SHADOWMAP_TYPE_PCF', tone: 'cineon', maps: true },
};
const materials = {
	basic: {}, lambert: {}, phong: {}, toon: {}, matcap: {}, normal: {}, points: {}, dashed: {},
	standard: { STANDARD: '' }, physical: { STANDARD: '', PHYSICAL: '' },
	depth: {}, distanceRGBA: {}, shadow: {}, sprite: {}, background: {}, backgroundCube: {}, cube: {}, equirect: {},
};

fs.mkdirSync(out, { recursive: true });
const seen = new Set();
let written = 0;
for (const [material, defines] of Object.entries(materials)) {
	const lib = ShaderLib[material];
	if (!lib) throw new Error(`no ShaderLib.${material}`);
	for (const [name, c] of Object.entries(configurations)) {
		for (const stage of ['vertex', 'fragment']) {
			const body = stage === 'vertex' ? lib.vertexShader : lib.fragmentShader;
			const shaderName = `${material}-${name}`;
			let text = unrollLoops(replaceNums(resolveIncludes(body), c.lights));
			text = replaceNums(prefix(c, stage, defines, shaderName), c.lights) + text;
			if (seen.has(text)) continue;
			seen.add(text);
			fs.writeFileSync(path.join(out, `${shaderName}.${stage === 'vertex' ? 'vert' : 'frag'}`), text);
			written++;
		}
	}
}
console.log(`${written} shaders`);
