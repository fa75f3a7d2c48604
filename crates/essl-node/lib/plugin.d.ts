import type {CheckOptions} from '../index.js';

/** Options of the Vite/Rollup plugin and the webpack loader. */
export interface EsslPluginOptions
  extends Pick<CheckOptions, 'target' | 'defines' | 'includeDirs' | 'preset' | 'config' | 'rules' | 'lints' | 'denyWarnings' | 'variants'> {
  /** Files to check (substrings or RegExps); default every shader file and script. */
  include?: string | RegExp | (string | RegExp)[];
  /** Files to leave (default: those under node_modules). */
  exclude?: string | RegExp | (string | RegExp)[];
  /** Warnings fail the build too. */
  failOnWarnings?: boolean;
  /** Minify imported shader files' text (comments, white space, local names; uniform,
   * attribute and varying names kept), checked again before it is used (default false).
   * Shaders inside JS/TS modules and shaders under a `preset` are left as they are. */
  minify?: boolean;
  /** Load bare shader imports as modules exporting their text (default true). */
  load?: boolean;
  /** Keep checks that found no error between builds (Vite/Rollup; default true:
   * `node_modules/.cache/essl` under Vite's root or the working folder), or the folder to
   * keep them in; `false` keeps none. The webpack loader uses webpack's cache instead. */
  cache?: boolean | string;
}

/** The plugin: `plugins: [essl({preset: 'three'})]`. */
export default function essl(options?: EsslPluginOptions): {
  name: 'essl';
  enforce: 'pre';
  configResolved(config: {command: string; root?: string}): void;
  buildStart(): void;
  /** Keeps the checks in `vite dev` and watch mode. */
  buildEnd(): void;
  /** Waits for the checks a one-shot build did not wait for; fails the build on an error. */
  generateBundle(): Promise<void>;
  /** A bare shader import's module; `filter`: the ids the bundler calls it for (Rollup
   * 4.38, Vite 6.3; older bundlers call it for every module). */
  load: {filter: {id: RegExp}; handler(id: string): string | null};
  /** Checks a shader file or a script; `filter` as `load`'s. */
  transform: {
    filter: {id: RegExp};
    handler(code: string, id: string): Promise<{code: string; map: null} | null>;
  };
};
