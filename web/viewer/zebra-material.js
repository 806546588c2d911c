// Zebra stripes (reflection lines) from the exact per-vertex normals the solver gives.
// The environment is a sphere at infinity painted with bands of equal angular width
// about an axis d that lies in the screen plane at `angle` from the screen's x axis.
// Per fragment, in view space (camera at the origin):
//   v = normalize(P)                     the ray from the eye to the point
//   r = reflect(v, n) = v - 2 (n·v) n    the reflected ray (n faced to the eye)
//   s = asin(r·d) / width                the reflected ray's latitude about d, in bands
//   colour = light where sin(π s) > 0, dark otherwise (antialiased over fwidth(s))
// A jump in the stripes shows a G0 gap, a kink a G1 corner, a change of their spacing a
// curvature (G2) jump. Back faces use -n, so open patches show stripes from both sides.
import * as THREE from 'three';

const vertexShader = /* glsl */ `
varying vec3 vNormal;
varying vec3 vViewPosition;
void main() {
  vec4 mv = modelViewMatrix * vec4(position, 1.0);
  vViewPosition = mv.xyz;
  vNormal = normalMatrix * normal;
  gl_Position = projectionMatrix * mv;
}`;

const fragmentShader = /* glsl */ `
uniform float angle;   // direction of the axis d in the screen plane, radians
uniform float width;   // angular width of one band, radians
uniform vec3 light;
uniform vec3 dark;
varying vec3 vNormal;
varying vec3 vViewPosition;
const float PI = 3.141592653589793;
void main() {
  float len = length(vNormal);
  if (len < 1e-6) { gl_FragColor = vec4(0.5, 0.5, 0.5, 1.0); return; } // a pole: no normal
  vec3 n = vNormal / len;
  if (!gl_FrontFacing) n = -n;
  vec3 v = normalize(vViewPosition);
  vec3 r = reflect(v, n);
  vec3 d = vec3(cos(angle), sin(angle), 0.0);
  float s = asin(clamp(dot(r, d), -1.0, 1.0)) / width;
  float aa = PI * max(fwidth(s), 1e-4);
  float t = smoothstep(-aa, aa, sin(PI * s));
  gl_FragColor = vec4(mix(dark, light, t), 1.0);
}`;

/** { angleDeg, widthDeg } -> a ShaderMaterial; update with setZebra(material, opts). */
export function createZebraMaterial({ angleDeg = 90, widthDeg = 6 } = {}) {
  const material = new THREE.ShaderMaterial({
    name: 'zebra',
    uniforms: {
      angle: { value: 0 },
      width: { value: 0.1 },
      light: { value: new THREE.Color(0.95, 0.95, 0.95) },
      dark: { value: new THREE.Color(0.06, 0.06, 0.07) },
    },
    vertexShader,
    fragmentShader,
    side: THREE.DoubleSide,
    polygonOffset: true, // the wireframe overlay draws on top without z-fighting
    polygonOffsetFactor: 1,
    polygonOffsetUnits: 1,
  });
  setZebra(material, { angleDeg, widthDeg });
  return material;
}

export function setZebra(material, { angleDeg, widthDeg }) {
  if (Number.isFinite(angleDeg)) material.uniforms.angle.value = THREE.MathUtils.degToRad(angleDeg);
  if (Number.isFinite(widthDeg) && widthDeg > 0) material.uniforms.width.value = THREE.MathUtils.degToRad(widthDeg);
}
