-- API tokens that expire (the hardening issue): `cad2mo token create --expires-in 30d`.
--
-- tokens.expires_at: RFC 3339 UTC like created_at; NULL for a token that never expires. A token
-- at or past it is refused by the service.
ALTER TABLE tokens ADD COLUMN expires_at TEXT;
