// The stereo eyes of the 3D view (side-by-side and dual output; the anaglyph uses the same
// numbers): the eyes are a thirtieth of the viewing distance apart (the 1/30 rule of stereo
// photography, so models of millimetres and of metres look alike), along the camera's right,
// looking parallel with off-axis frusta that converge at the orbit target: the target has no
// parallax and sits at the screen's depth, nearer parts stand out of it. No DOM: unit-tested.

import { PerspectiveCamera, StereoCamera } from 'three';

/** The distance between the eyes for a viewing distance. */
export function eyeSeparation(distance) {
  return distance > 0 ? distance / 30 : 0;
}

/**
 * One eye ('left' or 'right') of `camera` (a PerspectiveCamera looking at a point `distance`
 * ahead) for a viewport of aspect `aspect`. `rig` ({stereo, base}) holds the reused cameras;
 * the returned camera is the rig's and changes with the next call for the same side.
 */
export function eyeCamera(rig, camera, distance, side, aspect) {
  const stereo = (rig.stereo ||= new StereoCamera());
  const base = (rig.base ||= new PerspectiveCamera());
  base.copy(camera);
  base.aspect = aspect;
  base.focus = distance; // convergence at the target
  base.updateProjectionMatrix();
  base.updateMatrixWorld();
  stereo.eyeSep = eyeSeparation(distance);
  stereo.aspect = 1; // each eye keeps the viewport's proportions (full side-by-side)
  stereo.update(base);
  const eye = side === 'right' ? stereo.cameraR : stereo.cameraL;
  eye.updateMatrixWorld();
  return eye;
}
