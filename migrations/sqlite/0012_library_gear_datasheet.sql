-- Issue 27: gear units of the catalogue carry their backlash and mass; the rotary gear classes get
-- two datasheet parameters for them (never Modelica modifiers, optional per instance):
--   backlash (rad): maximum torsional backlash at the output (standard version);
--   m (kg): mass (weight) of the gear unit.
--
-- Installations seeded before receive them on the seeded gear classes, identified by their fixed
-- ids and only while they still have the seed's Modelica class, after the class's last parameter;
-- a parameter of that name the user already gave the class is kept (INSERT OR IGNORE). The texts
-- are those of engine/src/library/seed.rs. A new installation (no class yet) is seeded after the
-- migrations and this finds nothing to change. The catalogue gear instances themselves arrive
-- through crate::store::library::seed_new_instances (migration 0011).
WITH new_parameter (class_id, modelica_class, k, name, unit, comment) AS (VALUES
    ('081e59da-554a-4b0c-bd5a-7f03409fb279', 'Modelica.Mechanics.Rotational.Components.IdealGear', 1, 'backlash', 'rad', 'Datasheet: maximum torsional backlash at the output (standard version)'),
    ('081e59da-554a-4b0c-bd5a-7f03409fb279', 'Modelica.Mechanics.Rotational.Components.IdealGear', 2, 'm', 'kg', 'Datasheet: mass (weight) of the gear unit'),
    ('10ace2d9-1eef-4be8-b0c1-ba992d043a94', 'cad2mo.Drives.Gears.Efficiency', 1, 'backlash', 'rad', 'Datasheet: maximum torsional backlash at the output (standard version)'),
    ('10ace2d9-1eef-4be8-b0c1-ba992d043a94', 'cad2mo.Drives.Gears.Efficiency', 2, 'm', 'kg', 'Datasheet: mass (weight) of the gear unit')
)
INSERT OR IGNORE INTO library_parameters
    (class_id, name, position, type, unit, min_value, max_value, editable, datasheet, default_json, comment)
SELECT c.id, n.name,
       (SELECT COALESCE(MAX(p.position), -1) FROM library_parameters p WHERE p.class_id = c.id) + n.k,
       'Real', n.unit, 0.0, NULL, 0, 1, NULL, n.comment
FROM new_parameter n JOIN library_classes c ON c.id = n.class_id AND c.modelica_class = n.modelica_class
ORDER BY c.id, n.k;
