//! The motor library's domain: classes, parameters, instances, validation, XML (being written).
