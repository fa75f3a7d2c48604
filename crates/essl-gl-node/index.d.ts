// Types of the essl-gl package. WebGL's interfaces are generated from the Khronos IDL
// (lib/generated.d.ts, scripts/generate.mjs); the native addon's own types are napi-rs's
// (native.d.ts, generated from the Rust side by `napi build --dts`).
import type {
  WebGLRenderingContextBase, WebGLRenderingContextOverloads, WebGL2RenderingContextBase,
  WebGL2RenderingContextOverloads,
} from './lib/generated.js';

/** `WebGLContextAttributes`. */
export interface WebGLContextAttributes {
  alpha?: boolean;
  depth?: boolean;
  stencil?: boolean;
  antialias?: boolean;
  premultipliedAlpha?: boolean;
  preserveDrawingBuffer?: boolean;
  powerPreference?: 'default' | 'low-power' | 'high-performance';
  failIfMajorPerformanceCaveat?: boolean;
  desynchronized?: boolean;
  xrCompatible?: boolean;
}

/** Pixels as `ImageData` holds them: RGBA8, unpremultiplied, top row first. */
export interface ImageDataLike {
  readonly width: number;
  readonly height: number;
  readonly data: Uint8ClampedArray | Uint8Array;
}

/** A canvas of the `canvas` or `@napi-rs/canvas` packages (read through its 2D context). */
export interface CanvasLike {
  readonly width: number;
  readonly height: number;
  getContext(type: '2d'): unknown;
}

/** The `TexImageSource`s a Node program can have. */
export type TexImageSource = ImageDataLike | CanvasLike | Canvas;

export declare class WebGLObject {
  private constructor();
  label: string;
}
export declare class WebGLBuffer extends WebGLObject { private readonly __webglBuffer: void; }
export declare class WebGLFramebuffer extends WebGLObject { private readonly __webglFramebuffer: void; }
export declare class WebGLProgram extends WebGLObject { private readonly __webglProgram: void; }
export declare class WebGLRenderbuffer extends WebGLObject { private readonly __webglRenderbuffer: void; }
export declare class WebGLShader extends WebGLObject { private readonly __webglShader: void; }
export declare class WebGLTexture extends WebGLObject { private readonly __webglTexture: void; }
export declare class WebGLQuery extends WebGLObject { private readonly __webglQuery: void; }
export declare class WebGLSampler extends WebGLObject { private readonly __webglSampler: void; }
export declare class WebGLSync extends WebGLObject { private readonly __webglSync: void; }
export declare class WebGLTransformFeedback extends WebGLObject { private readonly __webglTransformFeedback: void; }
export declare class WebGLVertexArrayObject extends WebGLObject { private readonly __webglVertexArrayObject: void; }
export declare class WebGLUniformLocation { private constructor(); private readonly __webglUniformLocation: void; }
export declare class WebGLActiveInfo {
  private constructor();
  readonly name: string;
  readonly size: number;
  readonly type: number;
}
export declare class WebGLShaderPrecisionFormat {
  private constructor();
  readonly rangeMin: number;
  readonly rangeMax: number;
  readonly precision: number;
}

/** What essl-gl's contexts have beyond WebGL's IDL. */
export interface EsslGlExtras {
  /** Frees the GPU device and memory now; the context is lost for good. */
  destroy(): void;
  /** Whether `destroy()` ran. */
  readonly destroyed: boolean;
  /** Gives the drawing buffer (and the canvas) a new size. */
  resize(width: number, height: number): void;
  /** The drawing buffer as a PNG file; `null` when the context is lost. */
  toPNG(): Buffer | null;
  /** The drawing buffer as RGBA8 pixels, top row first. */
  getImageData(): ImageDataLike;
}

interface ContextAttributesOfCanvas {
  readonly canvas: Canvas | object;
  readonly drawingBufferWidth: number;
  readonly drawingBufferHeight: number;
  readonly drawingBufferFormat: number;
  drawingBufferColorSpace: 'srgb' | 'display-p3';
  unpackColorSpace: 'srgb' | 'display-p3';
}

export interface WebGLRenderingContext
  extends WebGLRenderingContextBase, WebGLRenderingContextOverloads, ContextAttributesOfCanvas, EsslGlExtras {}
export declare const WebGLRenderingContext: {
  prototype: WebGLRenderingContext;
  readonly [constant: string]: unknown;
};

export interface WebGL2RenderingContext
  extends WebGLRenderingContextBase, WebGL2RenderingContextBase, WebGL2RenderingContextOverloads,
    ContextAttributesOfCanvas, EsslGlExtras {}
export declare const WebGL2RenderingContext: {
  prototype: WebGL2RenderingContext;
  readonly [constant: string]: unknown;
};

/** A canvas for programs without a DOM. */
export declare class Canvas extends EventTarget {
  constructor(width?: number, height?: number);
  width: number;
  height: number;
  readonly clientWidth: number;
  readonly clientHeight: number;
  style: Record<string, string>;
  getBoundingClientRect(): { x: number; y: number; left: number; top: number; right: number; bottom: number; width: number; height: number };
  getContext(type: 'webgl2', attributes?: WebGLContextAttributes): WebGL2RenderingContext | null;
  getContext(type: 'webgl' | 'experimental-webgl', attributes?: WebGLContextAttributes): WebGLRenderingContext | null;
  getContext(type: string, attributes?: WebGLContextAttributes): null;
  /** The drawing buffer as a PNG file. */
  toBuffer(): Buffer;
}

/**
 * A WebGL context of `width` × `height` without a DOM (its `canvas` is a `Canvas`). Throws an
 * `Error` naming the package to install when there is no Vulkan driver.
 */
export declare function createContext(width: number, height: number, attributes?: WebGLContextAttributes, options?: { version?: 2 }): WebGL2RenderingContext;
export declare function createContext(width: number, height: number, attributes: WebGLContextAttributes | undefined, options: { version: 1 }): WebGLRenderingContext;

/** The context of `type` for a canvas-like object (made at its width and height). */
export declare function contextFor(canvas: { width: number; height: number }, type: string, attributes?: WebGLContextAttributes): WebGLRenderingContext | WebGL2RenderingContext | null;

/** Resizes the drawing buffer of `canvas`'s context to the canvas's size. */
export declare function resizeFor(canvas: object): void;

/** Makes a jsdom window's `<canvas>` elements answer `getContext('webgl2' | 'webgl')` with essl-gl. */
export declare function installInWindow(window: object): void;
