// What the solver module needs of the engine beyond WebAssembly 1.0: its per-vertex loops
// use fixed-width SIMD (-msimd128, 128 bits). Every browser the page supports has it
// (Chrome and Edge 91+, Firefox 89+, Safari 16.4+), so there is no scalar build; a browser
// that lacks it is told so by name instead of seeing the engine's CompileError.

// The smallest module that uses a v128 value: (func (result v128) i32.const 0 i8x16.splat
// i8x16.popcnt). It validates exactly where fixed-width SIMD is supported.
const SIMD_PROBE = Uint8Array.of(
  0x00, 0x61, 0x73, 0x6d, 0x01, 0x00, 0x00, 0x00, // magic, version 1
  0x01, 0x05, 0x01, 0x60, 0x00, 0x01, 0x7b, // type section: () -> v128
  0x03, 0x02, 0x01, 0x00, // function section: one function of type 0
  0x0a, 0x0a, 0x01, 0x08, 0x00, 0x41, 0x00, 0xfd, 0x0f, 0xfd, 0x62, 0x0b, // code
);

export const SIMD_MISSING = 'this browser cannot run the solver: it lacks WebAssembly SIMD '
  + '(Chrome or Edge 91+, Firefox 89+, Safari 16.4+ have it)';

/** True when the engine validates a module that uses fixed-width SIMD. */
export function hasWasmSimd(wasm = globalThis.WebAssembly) {
  try {
    return !!wasm && typeof wasm.validate === 'function' && wasm.validate(SIMD_PROBE);
  } catch {
    return false;
  }
}
