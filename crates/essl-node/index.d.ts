/** A place in a file: 1-based line, 1-based column in characters, and byte offset. */
export interface Position {
  line: number;
  column: number;
  offset: number;
}

/** A range of a file. */
export interface Range {
  start: Position;
  end: Position;
}

/** A text edit of a fix. */
export interface Edit {
  range: Range;
  text: string;
}

/** A diagnostic, on the file and line the author wrote (through includes and host files). */
export interface Diagnostic {
  /** A stable kebab-case id (`undeclared-identifier`, `pow-negative-base`); `essl explain CODE`. */
  code: string;
  severity: 'error' | 'warning' | 'note';
  message: string;
  /** The file it points into; null for a link error that points into neither shader. */
  file: string | null;
  range: Range | null;
  /** What the primary range shows. */
  label: string;
  secondary: {range: Range; message: string}[];
  notes: string[];
  help: string | null;
  fix: {message: string; applicability: 'certain' | 'suggested'; edits: Edit[]} | null;
  /** The rustc-style text (`error[code]: …` with the source line and labels). */
  rendered: string;
}

/** One checked shader. */
export interface CheckedShader {
  file: string;
  stage: 'vertex' | 'fragment';
  /** The name its host gives it (the variable a literal is assigned to, a tag's id). */
  name: string | null;
  /** Where its text starts in its host file, for a shader inside JS/TS or HTML. */
  embeddedAt: Position | null;
  ok: boolean;
  /** The text WebGL is given: `#include`s in place (null where one could not be followed). */
  text: string | null;
  /** The files that text was read from. */
  files: string[];
  diagnostics: Diagnostic[];
}

/** An active uniform as `getActiveUniform` reports it. */
export interface ActiveUniform {
  name: string;
  /** WebGL's type name (`FLOAT_VEC3`, `SAMPLER_2D`). */
  type: string;
  size: number;
}

/** An active attribute as `getActiveAttrib` reports it, with its location. */
export interface ActiveAttribute extends ActiveUniform {
  location: number;
}

/** A linked program. */
export interface CheckedProgram {
  /** Indices of its shaders in `shaders`. */
  vertex: number;
  fragment: number;
  /** Whether both shaders compiled, so that the link says something of the program. */
  linked: boolean;
  ok: boolean;
  /** WebGL's `getProgramInfoLog`. */
  log: string;
  uniforms: ActiveUniform[];
  attributes: ActiveAttribute[];
  diagnostics: Diagnostic[];
}

/** Options of `check`, `link` and `translate`, as `essl.toml` has them. */
export interface CheckOptions {
  /** The file the text is checked as: its extension gives the stage (`.vert`, `.frag`) or says
   * it is a JS/TS or HTML file holding shaders; `#include`s, `essl.toml` and a preset's
   * package are looked for from its folder. Default: `shader.vert`/`shader.frag` by `stage`. */
  filename?: string;
  /** The stage of a text whose name does not give one (`shader.glsl`, the default name); a
   * stage that contradicts `filename`'s extension is a `TypeError`. */
  stage?: 'vertex' | 'fragment';
  target?: 'webgl1' | 'webgl2';
  /** Macros defined as the API would (`{USE_FOG: 1}`; `true` is 1, `false` leaves it out). */
  defines?: Record<string, string | number | boolean>;
  /** Folders `#include "…"` searches after the file's own. */
  includeDirs?: string[];
  /** Follow `#include` (default true, as vite-plugin-glsl does). */
  includes?: boolean;
  /** Check as a library assembles its shaders: three.js materials, luma.gl/deck.gl programs. */
  preset?: 'three' | 'luma';
  /** One `essl.toml` for everything instead of each folder's nearest. */
  config?: string;
  /** Lint rule levels after essl.toml's (`{'pow-negative-base': 'deny'}`, `{all: 'allow'}`). */
  rules?: Record<string, 'allow' | 'note' | 'warn' | 'deny'>;
  /** Run the numerical-hazard lints (default true). */
  lints?: boolean;
  /** Link the pairs a file makes plain (default true). */
  link?: boolean;
  /** Every warning counts as an error. */
  denyWarnings?: boolean;
  /** How many `#ifdef` configurations besides the one `defines` selects the lints also check
   * (each flag's code, then every flag together), as essl.toml's `variants`: 64 by default,
   * `false` or 0 for none, `true` for the default. */
  variants?: number | boolean;
}

/** What `check` returns. */
export interface CheckResult {
  shaders: CheckedShader[];
  programs: CheckedProgram[];
  /** Every diagnostic: the shaders', then the programs'. */
  diagnostics: Diagnostic[];
  errors: number;
  warnings: number;
  ok: boolean;
}

/** Checks a shader, or every shader of a JS/TS or HTML file, as a browser compiles them. */
export function check(source: string, options?: CheckOptions): CheckResult;

/** `check` off the JavaScript thread, for a bundler's many modules: the checks asked for while
 * others run go to the addon together, on threads of Node's pool (one per core but one, at
 * most 4, at least 1). */
export function checkAsync(source: string, options?: CheckOptions): Promise<CheckResult>;

/** Options of `minify`: those of `check`, and whether local names are shortened. */
export interface MinifyOptions extends Omit<CheckOptions, 'preset'> {
  /** Shorten local variables, parameters and user functions (default true); false removes
   * comments and white space only. */
  rename?: boolean;
}

/** What `minify` returns: the check's result, and the minified text when it has no errors. */
export interface MinifyResult extends CheckResult {
  /** The minified text, compiled again and its interface compared with the original's; null
   * for a shader with errors (see `diagnostics`). */
  text: string | null;
  /** Each renamed local name and its new one. Uniforms, attributes, varyings, outputs, block
   * and struct names and members are never renamed. */
  renamed: Record<string, string>;
}

/** Minifies one shader's text (comments, white space, local names) after checking it. A
 * shader with errors is not minified; an output that would not compile or would change the
 * interface throws an Error rather than come back. */
export function minify(source: string, options?: MinifyOptions): MinifyResult;

/** `minify` on a thread of Node's pool. */
export function minifyAsync(source: string, options?: MinifyOptions): Promise<MinifyResult>;

/** What `link` returns: the program, and each shader's result. */
export interface LinkResult extends Omit<CheckedProgram, 'vertex' | 'fragment'> {
  vertex: CheckedShader;
  fragment: CheckedShader;
}

/** Checks both shaders and links them as `linkProgram` does. */
export function link(
  vertex: string,
  fragment: string,
  options?: Omit<CheckOptions, 'filename' | 'stage'> & {vertexFilename?: string; fragmentFilename?: string},
): LinkResult;

/** Where the host puts each uniform, sampler and attribute of a translated program. */
export type BindingMap = Record<string, unknown>;

/** Translates a program to WGSL, SPIR-V (words), MSL, HLSL or GLSL, with its binding map. */
export function translate(
  vertex: string,
  fragment: string,
  options?: Omit<CheckOptions, 'filename' | 'stage'> & {to?: 'wgsl' | 'spirv' | 'msl' | 'hlsl' | 'glsl'},
): {vertex: string | Uint32Array; fragment: string | Uint32Array; bindings: BindingMap};

/** The rustc-style text of diagnostics (or of a result's). */
export function format(diagnostics: Diagnostic[] | {diagnostics: Diagnostic[]}): string;

/** Runs the `essl` command (`['lint', 'src/']`) in this process; its exit status. */
export function runCli(args: string[]): number;
