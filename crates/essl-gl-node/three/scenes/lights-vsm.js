// The same lights with VSM shadows.
import * as THREE from 'three';
import { lightsScene } from './lights-pcf.js';

export function create(renderer, width, height) {
  return lightsScene(renderer, width, height, THREE.VSMShadowMap);
}
