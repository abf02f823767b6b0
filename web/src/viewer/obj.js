// The package's collision shapes (Resources/Collision/<body>.obj, in the body's CS1 frame,
// metres) as flat arrays for a three.js BufferGeometry: vertices ("v x y z") and triangles
// ("f a b c", 1-based, "a/b/c" forms and negative indices accepted; polygons fanned).

/** {positions: number[] (xyz per vertex), indices: number[] (three per triangle)} of an OBJ text. */
export function parseObj(text) {
  const positions = [];
  const indices = [];
  for (const raw of String(text).split('\n')) {
    const line = raw.trim();
    if (line.startsWith('v ')) {
      const [x, y, z] = line.slice(2).trim().split(/\s+/).map(Number);
      if (![x, y, z].every(Number.isFinite)) throw new Error(`bad vertex line: ${line}`);
      positions.push(x, y, z);
    } else if (line.startsWith('f ')) {
      const n = positions.length / 3;
      const ids = line
        .slice(2)
        .trim()
        .split(/\s+/)
        .map((t) => {
          const i = parseInt(t.split('/')[0], 10);
          return i < 0 ? n + i : i - 1;
        });
      if (ids.length < 3 || ids.some((i) => !Number.isInteger(i) || i < 0 || i >= n)) throw new Error(`bad face line: ${line}`);
      for (let k = 1; k + 1 < ids.length; k++) indices.push(ids[0], ids[k], ids[k + 1]);
    }
  }
  return { positions, indices };
}
