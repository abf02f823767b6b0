-- Issue 27: the seed library grows (catalogue instances); installations seeded before receive the
-- instances they have not been offered yet (crate::store::library::seed_new_instances), and never
-- again one the user deleted.
--
-- library_seed_offered.id: a seed instance id already offered to this installation (inserted, or
-- skipped because its class was gone or its name taken). An installation with a library was
-- seeded with the first seed (the nine instances below): they count as offered, so one the user
-- deleted is not brought back. A new installation (no class yet) records its seed when it seeds.
CREATE TABLE library_seed_offered (
    id TEXT PRIMARY KEY
);

INSERT INTO library_seed_offered (id)
SELECT s.id FROM (
    SELECT 'a204da99-dd36-4642-91d0-a61534935347' AS id
    UNION ALL SELECT '3cc686f6-fa23-4afb-9f9b-fe3c2b0b7a56'
    UNION ALL SELECT 'ff8d8ade-6252-45e7-9e97-204bce4f2f2d'
    UNION ALL SELECT 'ae1c622f-2892-40d8-95ef-0f7390777269'
    UNION ALL SELECT '05ea8371-f744-4b39-8683-e42bcf2a4e2a'
    UNION ALL SELECT '114caede-7ffb-45ea-b87d-177f3f8c80cd'
    UNION ALL SELECT '7255aafb-a3a5-4ca2-83a5-e57f136ff918'
    UNION ALL SELECT '111ab6e0-9fec-4319-a1f0-7823f62e5ae4'
    UNION ALL SELECT '42d928a7-a033-47a5-8545-33f2b4153faa'
) AS s
WHERE EXISTS (SELECT 1 FROM library_classes);
