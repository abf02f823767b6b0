-- Datasheet parameters of library classes (issue 12, drive sizing).
--
-- The drive sizing (server/src/sizing/) needs catalog values that are not Modelica parameters of
-- the classes: a motor's nominal torque, peak torque and maximum speed, a gear's rated and peak
-- output torque, maximum input speed and inertia. They are library parameters like the others
-- (typed, with units and limits, shown by the API, exchanged in the XML), marked as datasheet
-- values: never written as Modelica modifiers, and optional per instance (a check that needs a
-- missing one is reported as not evaluated).
--
-- library_parameters.datasheet: 1 for a datasheet value, 0 (every existing parameter) for a
-- Modelica parameter.
ALTER TABLE library_parameters ADD COLUMN datasheet INTEGER NOT NULL DEFAULT 0;

-- Existing installations were seeded before these parameters existed (a new installation is
-- seeded after the migrations, from server/src/library/seed.rs, and this part then finds no
-- class to change). Add them to the seeded classes, identified by their fixed ids and only while
-- they still have the seed's Modelica class, after the class's last parameter; a parameter of that
-- name the user already gave the class is kept (INSERT OR IGNORE). The texts are those of
-- seed.rs; store::library's tests check that an old seed migrated here equals the new seed.
WITH new_parameter (class_id, modelica_class, k, name, unit, comment) AS (VALUES
    ('93162c18-a028-4dbb-a9a7-c37bb6da9e15', 'cad2mo.Drives.Motors.DCPermanentMagnet', 1, 'T_nom', 'N.m', 'Datasheet: nominal torque (max. continuous torque, S1)'),
    ('93162c18-a028-4dbb-a9a7-c37bb6da9e15', 'cad2mo.Drives.Motors.DCPermanentMagnet', 2, 'T_peak', 'N.m', 'Datasheet: peak torque allowed for short times (intermittent operation)'),
    ('93162c18-a028-4dbb-a9a7-c37bb6da9e15', 'cad2mo.Drives.Motors.DCPermanentMagnet', 3, 'w_max', 'rad/s', 'Datasheet: maximum permissible speed'),
    ('22a8fc74-4da7-4531-a1a0-75fb5313705d', 'Modelica.Electrical.Machines.BasicMachines.DCMachines.DC_PermanentMagnet', 1, 'T_nom', 'N.m', 'Datasheet: nominal torque (max. continuous torque, S1)'),
    ('22a8fc74-4da7-4531-a1a0-75fb5313705d', 'Modelica.Electrical.Machines.BasicMachines.DCMachines.DC_PermanentMagnet', 2, 'T_peak', 'N.m', 'Datasheet: peak torque allowed for short times (intermittent operation)'),
    ('22a8fc74-4da7-4531-a1a0-75fb5313705d', 'Modelica.Electrical.Machines.BasicMachines.DCMachines.DC_PermanentMagnet', 3, 'w_max', 'rad/s', 'Datasheet: maximum permissible speed'),
    ('081e59da-554a-4b0c-bd5a-7f03409fb279', 'Modelica.Mechanics.Rotational.Components.IdealGear', 1, 'T_rated', 'N.m', 'Datasheet: rated (max. continuous) output torque'),
    ('081e59da-554a-4b0c-bd5a-7f03409fb279', 'Modelica.Mechanics.Rotational.Components.IdealGear', 2, 'T_peak', 'N.m', 'Datasheet: limit for repeated peak output torque (intermittent)'),
    ('081e59da-554a-4b0c-bd5a-7f03409fb279', 'Modelica.Mechanics.Rotational.Components.IdealGear', 3, 'w_in_max', 'rad/s', 'Datasheet: maximum input speed'),
    ('081e59da-554a-4b0c-bd5a-7f03409fb279', 'Modelica.Mechanics.Rotational.Components.IdealGear', 4, 'J_in', 'kg.m2', 'Datasheet: moment of inertia of the gear referred to its input (motor) shaft'),
    ('10ace2d9-1eef-4be8-b0c1-ba992d043a94', 'cad2mo.Drives.Gears.Efficiency', 1, 'T_rated', 'N.m', 'Datasheet: rated (max. continuous) output torque'),
    ('10ace2d9-1eef-4be8-b0c1-ba992d043a94', 'cad2mo.Drives.Gears.Efficiency', 2, 'T_peak', 'N.m', 'Datasheet: limit for repeated peak output torque (intermittent)'),
    ('10ace2d9-1eef-4be8-b0c1-ba992d043a94', 'cad2mo.Drives.Gears.Efficiency', 3, 'w_in_max', 'rad/s', 'Datasheet: maximum input speed'),
    ('10ace2d9-1eef-4be8-b0c1-ba992d043a94', 'cad2mo.Drives.Gears.Efficiency', 4, 'J_in', 'kg.m2', 'Datasheet: moment of inertia of the gear referred to its input (motor) shaft'),
    ('1d6bd1fa-9a39-47b1-86dc-e0162feea6eb', 'cad2mo.Drives.Gears.LeadScrew', 1, 'F_peak', 'N', 'Datasheet: maximum axial force of screw, nut and bearings'),
    ('1d6bd1fa-9a39-47b1-86dc-e0162feea6eb', 'cad2mo.Drives.Gears.LeadScrew', 2, 'w_in_max', 'rad/s', 'Datasheet: maximum input (screw or gearbox input) speed'),
    ('1d6bd1fa-9a39-47b1-86dc-e0162feea6eb', 'cad2mo.Drives.Gears.LeadScrew', 3, 'J_in', 'kg.m2', 'Datasheet: moment of inertia referred to the input (motor) shaft')
)
INSERT OR IGNORE INTO library_parameters
    (class_id, name, position, type, unit, min_value, max_value, editable, datasheet, default_json, comment)
SELECT c.id, n.name,
       (SELECT COALESCE(MAX(p.position), -1) FROM library_parameters p WHERE p.class_id = c.id) + n.k,
       'Real', n.unit, 0.0, NULL, 0, 1, NULL, n.comment
FROM new_parameter n JOIN library_classes c ON c.id = n.class_id AND c.modelica_class = n.modelica_class
ORDER BY c.id, n.k;

-- The seeded instances get the datasheet values the seed now has (values in SI units, as JSON
-- text exactly as seed.rs stores them: json_insert never overwrites a value already there) and
-- the sentence of their source that names them (or says why there are none). Only instances of
-- the seeded class that now has the datasheet parameters are touched.
UPDATE library_instances SET
    values_json = json_insert(values_json, '$.T_nom', json('0.17'), '$.w_max', json('1256.63706143592')),
    source = source || ' ' || 'Datasheet values for the drive sizing (same catalog): nominal torque (max. continuous torque) 170 mNm (= 30.2 mNm/A · (5.77 A - 0.137 A)), max. permissible speed 12000 rpm. maxon prints no peak torque besides the stall torque 2280 mNm at 24 V (the sizing''s voltage check covers the speed-torque line), so T_peak is left empty: the peak check then uses k·I_max, the current limit of the generated drive.'
WHERE id = 'a204da99-dd36-4642-91d0-a61534935347' AND class_id = '93162c18-a028-4dbb-a9a7-c37bb6da9e15'
  AND EXISTS (SELECT 1 FROM library_parameters
              WHERE class_id = '93162c18-a028-4dbb-a9a7-c37bb6da9e15' AND name = 'T_nom' AND datasheet = 1);
UPDATE library_instances SET
    source = source || ' ' || 'Datasheet values for the drive sizing (nominal torque, peak torque, max. speed) are not entered: not verified against the catalog.'
WHERE id = '3cc686f6-fa23-4afb-9f9b-fe3c2b0b7a56' AND class_id = '93162c18-a028-4dbb-a9a7-c37bb6da9e15'
  AND EXISTS (SELECT 1 FROM library_parameters
              WHERE class_id = '93162c18-a028-4dbb-a9a7-c37bb6da9e15' AND name = 'T_nom' AND datasheet = 1);
UPDATE library_instances SET
    source = source || ' ' || 'Datasheet values for the drive sizing (rated torque, peak torque, max. speed) are not entered: not verified against the data sheet.'
WHERE id = 'ff8d8ade-6252-45e7-9e97-204bce4f2f2d' AND class_id = '93162c18-a028-4dbb-a9a7-c37bb6da9e15'
  AND EXISTS (SELECT 1 FROM library_parameters
              WHERE class_id = '93162c18-a028-4dbb-a9a7-c37bb6da9e15' AND name = 'T_nom' AND datasheet = 1);
UPDATE library_instances SET
    source = source || ' ' || 'Datasheet values for the drive sizing (rated torque, peak torque, max. speed) are not entered: not verified against the data sheet.'
WHERE id = 'ae1c622f-2892-40d8-95ef-0f7390777269' AND class_id = '93162c18-a028-4dbb-a9a7-c37bb6da9e15'
  AND EXISTS (SELECT 1 FROM library_parameters
              WHERE class_id = '93162c18-a028-4dbb-a9a7-c37bb6da9e15' AND name = 'T_nom' AND datasheet = 1);
UPDATE library_instances SET
    values_json = json_insert(values_json, '$.T_nom', json('0.17'), '$.w_max', json('1256.63706143592')),
    source = source || ' ' || 'Datasheet values for the drive sizing (same catalog): nominal torque (max. continuous torque) 170 mNm, max. permissible speed 12000 rpm; no peak torque (maxon prints only the stall torque 2280 mNm at 24 V), so T_peak is left empty.'
WHERE id = '05ea8371-f744-4b39-8683-e42bcf2a4e2a' AND class_id = '22a8fc74-4da7-4531-a1a0-75fb5313705d'
  AND EXISTS (SELECT 1 FROM library_parameters
              WHERE class_id = '22a8fc74-4da7-4531-a1a0-75fb5313705d' AND name = 'T_nom' AND datasheet = 1);
UPDATE library_instances SET
    values_json = json_insert(values_json, '$.T_rated', json('31.0'), '$.T_peak', json('70.0'), '$.w_in_max', json('764.454212373516'), '$.J_in', json('7.9e-6')),
    source = source || ' ' || 'Datasheet values for the drive sizing, Harmonic Drive CSF component set catalog, size 17, ratio 100: rated torque at 2000 rpm input 31 Nm, limit for repeated peak torque 70 Nm, maximum input speed 7300 rpm (grease lubrication), moment of inertia 0.079·10⁻⁴ kg·m² (input side). Not used: limit for average torque 51 Nm, momentary peak torque 143 Nm, limit for average input speed 3500 rpm (grease). The ratings hold for ratio 100; at other ratios they differ.'
WHERE id = '114caede-7ffb-45ea-b87d-177f3f8c80cd' AND class_id = '081e59da-554a-4b0c-bd5a-7f03409fb279'
  AND EXISTS (SELECT 1 FROM library_parameters
              WHERE class_id = '081e59da-554a-4b0c-bd5a-7f03409fb279' AND name = 'T_rated' AND datasheet = 1);
UPDATE library_instances SET
    values_json = json_insert(values_json, '$.T_rated', json('15.0'), '$.T_peak', json('22.5'), '$.w_in_max', json('837.758040957278')),
    source = source || ' ' || 'Datasheet values for the drive sizing (same catalog, 3 stages): max. continuous torque 15 Nm, intermittently permissible torque at the gear output 22.5 Nm, max. motor shaft (input) speed 8000 rpm. The mass inertia is not entered (not verified).'
WHERE id = '7255aafb-a3a5-4ca2-83a5-e57f136ff918' AND class_id = '10ace2d9-1eef-4be8-b0c1-ba992d043a94'
  AND EXISTS (SELECT 1 FROM library_parameters
              WHERE class_id = '10ace2d9-1eef-4be8-b0c1-ba992d043a94' AND name = 'T_rated' AND datasheet = 1);
UPDATE library_instances SET
    source = source || ' ' || 'No datasheet values for the drive sizing: axial load ratings, critical speed and inertia depend on the length, nut and bearings.'
WHERE id = '111ab6e0-9fec-4319-a1f0-7823f62e5ae4' AND class_id = '1d6bd1fa-9a39-47b1-86dc-e0162feea6eb'
  AND EXISTS (SELECT 1 FROM library_parameters
              WHERE class_id = '1d6bd1fa-9a39-47b1-86dc-e0162feea6eb' AND name = 'F_peak' AND datasheet = 1);
