//! STL back end. See `write_binary`.
