// essl-gl for Node.js: WebGL 2 and WebGL 1 contexts on essl-gl (wgpu, Vulkan; headless on
// Mesa's lavapipe). See README.md.
export {
  WebGLObject, WebGLBuffer, WebGLFramebuffer, WebGLProgram, WebGLRenderbuffer, WebGLShader,
  WebGLTexture, WebGLQuery, WebGLSampler, WebGLSync, WebGLTransformFeedback,
  WebGLVertexArrayObject, WebGLUniformLocation, WebGLActiveInfo, WebGLShaderPrecisionFormat,
} from './lib/objects.js';
export { WebGLRenderingContext, WebGL2RenderingContext } from './lib/context.js';
export { Canvas, createContext, contextFor, resizeFor } from './lib/canvas.js';
export { installInWindow } from './lib/dom.js';
