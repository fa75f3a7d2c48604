// The scenes, by name, in the order reports list them.
export const SCENES = [
  'lights-pcf',
  'lights-vsm',
  'pbr-envmap',
  'msaa-target',
  'postprocessing',
  'instancing',
  'skinning-morph',
  'points-lines-sprites',
  'fog',
  'tone-mapping',
  'transmission',
  'materials',
];

/** Width and height every scene is drawn at. */
export const SIZE = [320, 240];
