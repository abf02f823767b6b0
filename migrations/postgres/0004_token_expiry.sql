-- PostgreSQL twin of migrations/sqlite/0004_token_expiry.sql: the same tables and columns (tests check it).
-- Types: INTEGER -> BIGINT, REAL -> DOUBLE PRECISION, TEXT -> TEXT COLLATE "C" (byte order,
-- like SQLite's). `rowid BIGINT GENERATED ALWAYS AS IDENTITY` stands in for SQLite's implicit
-- rowid (insertion order for ORDER BY ... rowid); the schema test leaves it out.

-- API tokens that expire (the hardening issue): `cad2mo token create --expires-in 30d`.
--
-- tokens.expires_at: RFC 3339 UTC like created_at; NULL for a token that never expires. A token
-- at or past it is refused by the service.
ALTER TABLE tokens ADD COLUMN expires_at TEXT COLLATE "C";
