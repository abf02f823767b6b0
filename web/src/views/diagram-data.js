// The Modelica diagram's pure parts: which icon a component gets from its class (drawn from
// primitives in the spirit of the MSL icons, no copied graphics), and how its name is labelled:
// in screen pixels whatever the zoom, hidden when the component is too small on screen to carry it.

/** The icon kind of a Modelica class name (MSL or one we generate). */
export function componentKind(className) {
  const c = String(className ?? '');
  const last = c.split('.').pop();
  if (/^World$/.test(last)) return 'world';
  if (/Fixed$/.test(last) && !/Translation|Rotation/.test(last)) return 'fixed';
  if (/^Fixed(Translation|Rotation)$|^FixedShape/.test(last)) return 'translation';
  if (/(Force|Torque)$/.test(last)) return 'force';
  if (/^Body|BodyShape|BodyBox|BodyCylinder|^Mass$/.test(last)) return 'body';
  if (/Revolute|Spherical|Universal|Cylindrical|Planar|FreeMotion/.test(last)) return 'revolute';
  if (/Prismatic/.test(last)) return 'prismatic';
  // Generated classes are known by their package (ARM.Motors.DCPermanentMagnet, ARM.Gears…).
  if (/Sensor/.test(last)) return 'sensor';
  if (/(^|\.)Drives?\.|^Drive|Drive$/.test(c)) return 'drive';
  if (/Motors?\.|Motor|DCPM|Servo/i.test(c)) return 'motor';
  if (/Gears?\.|Gear|Screw/i.test(c)) return 'gear';
  if (/Controllers?\.|Controller|Cascade|PID$|PI$/.test(c)) return 'controller';
  if (/Contact|Force|Torque|Collision/.test(c)) return 'force';
  return 'other';
}

export const LABEL_PX = 11; // label height on screen, CSS pixels
export const MIN_BOX_PX = 18; // below this on-screen width a component carries no label

/**
 * A label for a component `boxWidth` user units wide at `scale` screen pixels per user unit:
 * the font size in user units that makes LABEL_PX on screen, or hidden when the component is
 * narrower than MIN_BOX_PX on screen (its name would cover its neighbours).
 */
export function labelPlan(scale, boxWidth) {
  if (!(scale > 0) || boxWidth * scale < MIN_BOX_PX) return { visible: false, fontSize: 0 };
  return { visible: true, fontSize: LABEL_PX / scale };
}

/** The text of the SVG component's <title>: "Class name" → {className, name}. */
export function parseTitle(title) {
  const t = String(title ?? '').trim();
  const i = t.lastIndexOf(' ');
  return i < 0 ? { className: t, name: '' } : { className: t.slice(0, i), name: t.slice(i + 1) };
}

/**
 * The parameter rows of a Mechatronics drive component (drive_<joint>): the joint, the library
 * instances of its motor, gear and controller (by name), the gear ratio (the drive's own override
 * or the gear's value) and any other overridden values.
 * @param {string} joint
 * @param {object|undefined} drive  one of GET /api/models/{id}/drives' drives
 * @param {Map<string, {name: string, values?: object}>} instById  the library's instances
 * @returns {[string, string][]}
 */
export function driveParamRows(joint, drive, instById) {
  if (!drive) return [['Joint', joint], ['Drive', 'none stored for this joint']];
  const name = (id) => (id ? instById.get(id)?.name || id : '—');
  const rows = [['Joint', joint], ['Motor', name(drive.motor_instance)], ['Gear', name(drive.gear_instance)]];
  const ratio = drive.overrides?.gear?.ratio ?? instById.get(drive.gear_instance)?.values?.ratio;
  if (ratio !== undefined && ratio !== null) rows.push(['Ratio', String(ratio)]);
  rows.push(['Controller', name(drive.controller_instance)]);
  for (const [slot, values] of Object.entries(drive.overrides || {})) {
    for (const [k, v] of Object.entries(values || {})) if (!(slot === 'gear' && k === 'ratio')) rows.push([`${slot}.${k}`, String(v)]);
  }
  if (drive.status && drive.status !== 'active') rows.push(['Status', drive.status]);
  return rows;
}
