//! STL front end (ASCII and binary). See `parse`.
