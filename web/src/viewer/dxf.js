// The 3D faces of an ASCII DXF file (pure, unit-tested): what MSL's file shapes reference
// (modelica://Modelica/Resources/Data/Shapes/RobotR3/b0.dxf …). MSL's Types.ShapeType says a
// tool may read the DXF's 3-dimensional faces only, and that is what is read here: each 3DFACE
// entity's corners (group codes 10/20/30 … 13/23/33) as one triangle, or two when its fourth
// corner differs from its third. Other entities are skipped. Coordinates as written (MSL reads
// them in metres, in the shape's frame).

/**
 * @param {string} text  the DXF file
 * @param {string} [name]  the file's name, for error messages
 * @returns {{positions: Float32Array, faces: number}}  triangles (9 floats each) and 3DFACE count
 */
export function parseDxfFaces(text, name = 'the DXF file') {
  const lines = String(text).split(/\r\n|\r|\n/);
  if (lines.length < 2) throw new Error(`${name} is empty`);
  const out = [];
  let faces = 0;
  let face = null; // the corners of the 3DFACE being read
  const finish = () => {
    if (!face) return;
    const c = face.corners;
    for (let k = 0; k < 3; k++) {
      if (c[k].some((x) => !Number.isFinite(x))) throw new Error(`${name}: 3DFACE at line ${face.line} lacks corner ${k + 1}`);
    }
    faces += 1;
    out.push(...c[0], ...c[1], ...c[2]);
    const d = c[3];
    if (d.every(Number.isFinite) && d.some((x, i) => x !== c[2][i])) out.push(...c[0], ...c[2], ...d);
    face = null;
  };
  for (let i = 0; i + 1 < lines.length; i += 2) {
    const code = Number(lines[i].trim());
    if (!Number.isInteger(code) || lines[i].trim() === '') throw new Error(`${name}: line ${i + 1} is not a group code: "${lines[i].trim().slice(0, 40)}"`);
    const value = lines[i + 1].trim();
    if (code === 0) {
      finish();
      if (value === 'EOF') break;
      if (value === '3DFACE') face = { line: i + 2, corners: Array.from({ length: 4 }, () => [NaN, NaN, NaN]) };
      continue;
    }
    if (!face) continue;
    // 10..13 x, 20..23 y, 30..33 z of corners 1..4.
    const axis = Math.floor(code / 10) - 1;
    const corner = code % 10;
    if (axis >= 0 && axis <= 2 && corner <= 3 && code >= 10 && code <= 33) {
      const x = Number(value);
      if (!Number.isFinite(x)) throw new Error(`${name}: line ${i + 2}: "${value.slice(0, 40)}" is not a number (group ${code} of a 3DFACE)`);
      face.corners[corner][axis] = x;
    }
  }
  finish();
  if (!faces) throw new Error(`${name} has no 3DFACE entities (only the DXF's 3D faces are read)`);
  return { positions: new Float32Array(out), faces };
}

