//! Inline / EXTERNPROTO urls to bundle paths.

use crate::pipeline::front::bundle::{Bundle, BundleError};

/// Decodes `%XX` escapes (invalid ones are kept as written).
fn percent_decode(s: &str) -> String {
    let b = s.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'%' && i + 2 < b.len() {
            let hex = std::str::from_utf8(&b[i + 1..i + 3]).ok().and_then(|h| u8::from_str_radix(h, 16).ok());
            if let Some(v) = hex {
                out.push(v);
                i += 3;
                continue;
            }
        }
        out.push(b[i]);
        i += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// The bundle path `url` names when written in bundle file `from`: `#fragment` dropped, `file:`
/// and `%XX` decoded, `\` as `/`, relative to `from`'s folder with `..` resolved (climbing above
/// the bundle root drops the excess `..`), then [`Bundle::resolve`]'s exact, case-insensitive and
/// file-name lookups. Absolute paths and remote urls (`http://...`) are looked up by file name.
pub(super) fn resolve_url(bundle: &Bundle, from: &str, url: &str) -> Result<Option<String>, BundleError> {
    let mut u = url.trim();
    if let Some(i) = u.find('#') {
        u = &u[..i];
    }
    if let Some(i) = u.find('?') {
        u = &u[..i];
    }
    let lower = u.to_ascii_lowercase();
    let mut by_name_only = false;
    if lower.starts_with("file:") {
        u = u[5..].trim_start_matches('/');
        by_name_only = true;
    } else if let Some(i) = lower.find("://") {
        u = &u[i + 3..];
        by_name_only = true;
    }
    let decoded = percent_decode(u).replace('\\', "/");
    if decoded.starts_with('/') || decoded.as_bytes().get(1) == Some(&b':') {
        by_name_only = true;
    }
    let wanted = if by_name_only {
        decoded.rsplit('/').next().unwrap_or("").to_string()
    } else {
        let dir = from.rsplit_once('/').map(|(d, _)| d).unwrap_or("");
        let mut parts: Vec<&str> = dir.split('/').filter(|s| !s.is_empty()).collect();
        for seg in decoded.split('/') {
            match seg {
                "" | "." => {}
                ".." => {
                    parts.pop();
                }
                s => parts.push(s),
            }
        }
        parts.join("/")
    };
    if wanted.is_empty() {
        return Ok(None);
    }
    Ok(bundle.resolve("", &wanted)?.map(str::to_string))
}
