//! DXF back end. See `write`.
