// The Rollup plugin: the same plugin as `essl/vite` (Rollup ignores Vite's `enforce`).
export {default} from './vite.js';
