import lightVertex from './shaders/light.vert';
import lightFragment from './shaders/light.frag';
import {outline} from './materials.js';

export const shaders = {lightVertex, lightFragment, outline};
