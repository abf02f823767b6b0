//! Output bundle: the zip holding the package and the report.
