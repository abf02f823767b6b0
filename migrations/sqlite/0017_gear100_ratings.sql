-- Issue 27: the first seed's "Ideal gear 100:1" carried 31 Nm rated and 70 Nm repeated peak
-- torque as the Harmonic Drive CSF-17-100's, without a page to check them against; a public
-- transcription of Harmonic Drive's CSF-17-100-2UH product page prints other ratings. Both values
-- are removed (the sizing then names gear.T_rated and gear.T_peak as missing) and the source
-- says why. Installations seeded before get this unless their user edited the source or those
-- values.
UPDATE library_instances
SET values_json = json_remove(values_json, '$.T_rated', '$.T_peak'),
    source = 'Reduction 100:1 as of a strain-wave gear Harmonic Drive CSF-17-100 (catalog reduction ratio 100), modelled without losses. Datasheet values for the drive sizing as the first seed gave them from the Harmonic Drive CSF component set catalog, size 17 (values of the size, the same at every ratio; not checked again against a page): maximum input speed 7300 rpm (grease lubrication), moment of inertia 0.079·10⁻⁴ kg·m² (input side). T_rated and T_peak missing: the first seed entered 31 Nm rated torque and 70 Nm repeated peak torque (51 Nm average, 143 Nm momentary peak) as this size and ratio''s, but a public transcription of Harmonic Drive''s CSF-17-100-2UH product page prints other ratings (24 Nm rated, 54 Nm repeated peak, 108 Nm momentary peak) and no maker''s page at hand settles which are right, so neither is entered; the gear''s torque checks are then not evaluated and name gear.T_rated and gear.T_peak as missing.'
WHERE id = '114caede-7ffb-45ea-b87d-177f3f8c80cd'
  AND source = 'Reduction 100:1 as of a strain-wave gear Harmonic Drive CSF-17-100 (catalog reduction ratio 100), modelled without losses. Datasheet values for the drive sizing, Harmonic Drive CSF component set catalog, size 17, ratio 100: rated torque at 2000 rpm input 31 Nm, limit for repeated peak torque 70 Nm, maximum input speed 7300 rpm (grease lubrication), moment of inertia 0.079·10⁻⁴ kg·m² (input side). Not used: limit for average torque 51 Nm, momentary peak torque 143 Nm, limit for average input speed 3500 rpm (grease). The ratings hold for ratio 100; at other ratios they differ.'
  AND json_extract(values_json, '$.T_rated') = 31.0
  AND json_extract(values_json, '$.T_peak') = 70.0;
