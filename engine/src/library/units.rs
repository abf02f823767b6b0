//! The unit table: the units a library value may be given in, and their conversion to SI.
//!
//! Each unit maps to one SI unit of the same dimension (`"uH"` -> `"H"`) by a factor, given as a
//! ratio `num / den` so that decimal prefixes convert with one correctly rounded division
//! (82 uH = 82 / 1e6 H, exactly the double nearest 8.2e-5), plus an offset for degrees Celsius.
//! Two units are compatible when they map to the same SI unit. Parameters of library classes are
//! declared in SI units (the ones [`is_si`] accepts); values may be given in any unit of the table.
//!
//! The table is explicit on purpose: a handful of base units take the SI prefixes (G M k m u µ n),
//! everything else (rpm, g.cm2, mNm/A, %, degC, ...) is listed. No unit algebra is attempted.

use std::f64::consts::PI;

/// How a unit converts to its SI unit: `si = x * num / den + offset`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Unit {
    /// The SI unit of the same dimension (itself for SI units).
    pub si: &'static str,
    num: f64,
    den: f64,
    offset: f64,
}

impl Unit {
    const fn new(si: &'static str, num: f64, den: f64) -> Unit {
        Unit { si, num, den, offset: 0.0 }
    }

    fn is_identity(self) -> bool {
        self.num == self.den && self.offset == 0.0
    }

    fn si_value(self, x: f64) -> f64 {
        let scaled = if self.den == 1.0 {
            x * self.num
        } else if self.num == 1.0 {
            x / self.den
        } else {
            x * (self.num / self.den)
        };
        scaled + self.offset
    }

    fn value_in(self, x: f64) -> f64 {
        let x = x - self.offset;
        if self.num == 1.0 {
            x * self.den
        } else if self.den == 1.0 {
            x / self.num
        } else {
            x * (self.den / self.num)
        }
    }
}

/// SI units a parameter may be declared in (dimension "1" is a pure number).
const SI: &[&str] = &[
    "1",
    "m",
    "kg",
    "s",
    "A",
    "K",
    "rad",
    "V",
    "Ohm",
    "H",
    "W",
    "N",
    "N.m",
    "N.m/A",
    "kg.m2",
    "N.m.s/rad",
    "rad/s",
    "rad/s2",
    "m/s",
    "m/s2",
    "1/s",
    "1/K",
    "A.s/rad",
    "V.s/rad",
];

/// Base units that take the SI prefixes: (symbol, SI unit, num, den).
const PREFIXABLE: &[(&str, &str, f64, f64)] = &[
    ("Ohm", "Ohm", 1.0, 1.0),
    ("Ω", "Ohm", 1.0, 1.0),
    ("H", "H", 1.0, 1.0),
    ("V", "V", 1.0, 1.0),
    ("A", "A", 1.0, 1.0),
    ("s", "s", 1.0, 1.0),
    ("m", "m", 1.0, 1.0),
    ("W", "W", 1.0, 1.0),
    ("N", "N", 1.0, 1.0),
    ("N.m", "N.m", 1.0, 1.0),
    ("Nm", "N.m", 1.0, 1.0),
    ("rad", "rad", 1.0, 1.0),
    ("g", "kg", 1.0, 1e3),
];

/// SI prefixes: (symbol, power of ten).
const PREFIXES: &[(&str, i32)] = &[("G", 9), ("M", 6), ("k", 3), ("m", -3), ("u", -6), ("µ", -6), ("n", -9)];

/// Everything else, listed: (symbol, SI unit, num, den).
const LISTED: &[(&str, &str, f64, f64)] = &[
    // Pure numbers.
    ("%", "1", 1.0, 100.0),
    // Speeds.
    ("rpm", "rad/s", PI, 30.0),
    ("rev/min", "rad/s", PI, 30.0),
    ("deg/s", "rad/s", PI, 180.0),
    ("deg", "rad", PI, 180.0),
    ("arcmin", "rad", PI, 10800.0),
    ("rev", "rad", 2.0 * PI, 1.0),
    // Inertia.
    ("g.cm2", "kg.m2", 1.0, 1e7),
    ("gcm2", "kg.m2", 1.0, 1e7),
    ("g.mm2", "kg.m2", 1.0, 1e9),
    ("kg.cm2", "kg.m2", 1.0, 1e4),
    ("kg.mm2", "kg.m2", 1.0, 1e6),
    // Torque and back-EMF constants (1 N.m/A = 1 V.s/rad).
    ("Nm/A", "N.m/A", 1.0, 1.0),
    ("mNm/A", "N.m/A", 1.0, 1e3),
    ("mN.m/A", "N.m/A", 1.0, 1e3),
    ("V/(rad/s)", "V.s/rad", 1.0, 1.0),
    ("mV/rpm", "V.s/rad", 30.0, 1e3 * PI),
    ("V/krpm", "V.s/rad", 30.0, 1e3 * PI),
    // Viscous friction.
    ("N.m/(rad/s)", "N.m.s/rad", 1.0, 1.0),
    ("Nms/rad", "N.m.s/rad", 1.0, 1.0),
    ("mNm/rpm", "N.m.s/rad", 30.0, 1e3 * PI),
    ("mN.m/rpm", "N.m.s/rad", 30.0, 1e3 * PI),
    ("mN.m.s/rad", "N.m.s/rad", 1.0, 1e3),
    // Time.
    ("min", "s", 60.0, 1.0),
    ("h", "s", 3600.0, 1.0),
    // Temperature (degC has an offset; differences of 1 degC = 1 K are not expressible here).
    ("1/degC", "1/K", 1.0, 1.0),
    // Accelerations and linear speeds.
    ("mm/s", "m/s", 1.0, 1e3),
    ("1/min", "1/s", 1.0, 60.0),
];

/// Looks a unit up. `""` is not a unit (no unit at all) and is not found.
pub fn lookup(unit: &str) -> Option<Unit> {
    if unit == "degC" {
        return Some(Unit { si: "K", num: 1.0, den: 1.0, offset: 273.15 });
    }
    if let Some(si) = SI.iter().find(|s| **s == unit) {
        // "V.s/rad" is the same SI quantity as "N.m/A": both are SI, and they convert 1:1.
        let si = if *si == "V.s/rad" { "N.m/A" } else { si };
        return Some(Unit::new(si, 1.0, 1.0));
    }
    if let Some((_, si, num, den)) = LISTED.iter().find(|(s, ..)| *s == unit) {
        let si = if *si == "V.s/rad" { "N.m/A" } else { si };
        return Some(Unit::new(si, *num, *den));
    }
    for (base, si, num, den) in PREFIXABLE {
        if unit == *base {
            return Some(Unit::new(si, *num, *den));
        }
        if let Some(prefix) = unit.strip_suffix(base) {
            if let Some((_, p)) = PREFIXES.iter().find(|(s, _)| *s == prefix) {
                let scale = 10f64.powi(p.abs());
                let (num, den) = if *p > 0 { (num * scale, *den) } else { (*num, den * scale) };
                // kg = 1000 g = 1000/1000 kg: keep identities exact.
                let (num, den) = if num == den { (1.0, 1.0) } else { (num, den) };
                return Some(Unit::new(si, num, den));
            }
        }
    }
    None
}

/// Whether `unit` is an SI unit a parameter may be declared in.
pub fn is_si(unit: &str) -> bool {
    SI.contains(&unit)
}

/// The SI unit to declare instead of `unit`, when `unit` is a known non-SI unit.
pub fn si_of(unit: &str) -> Option<&'static str> {
    lookup(unit).map(|u| u.si)
}

/// The SI units, for messages.
pub fn si_units() -> &'static [&'static str] {
    SI
}

/// Why a value cannot be converted.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum UnitError {
    #[error("unknown unit \"{0}\"")]
    Unknown(String),
    #[error("\"{from}\" ({from_si}) cannot be converted to \"{to}\" ({to_si}): the dimensions differ")]
    Incompatible { from: String, from_si: &'static str, to: String, to_si: &'static str },
}

/// Converts `x` from unit `from` to unit `to`. A value that was actually converted is rounded to
/// 15 significant digits (far below any datasheet's precision), so that 30.2 mNm/A gives 0.0302
/// and not 0.030199999999999998; an identity conversion returns `x` unchanged.
pub fn convert(x: f64, from: &str, to: &str) -> Result<f64, UnitError> {
    if from == to {
        return Ok(x);
    }
    let f = lookup(from).ok_or_else(|| UnitError::Unknown(from.to_string()))?;
    let t = lookup(to).ok_or_else(|| UnitError::Unknown(to.to_string()))?;
    if f.si != t.si {
        return Err(UnitError::Incompatible { from: from.to_string(), from_si: f.si, to: to.to_string(), to_si: t.si });
    }
    if f.is_identity() && t.is_identity() {
        return Ok(x);
    }
    Ok(round15(t.value_in(f.si_value(x))))
}

/// Rounds to 15 significant digits (every decimal of up to 15 digits survives unchanged).
fn round15(x: f64) -> f64 {
    if !x.is_finite() || x == 0.0 {
        return x;
    }
    format!("{x:.14e}").parse().unwrap_or(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c(x: f64, from: &str, to: &str) -> f64 {
        convert(x, from, to).expect("converts")
    }

    #[test]
    fn prefixes_divide_exactly() {
        assert_eq!(c(82.0, "uH", "H"), 8.2e-5);
        assert_eq!(c(82.0, "µH", "H"), 8.2e-5);
        assert_eq!(c(0.0823, "mH", "H"), 8.23e-5);
        assert_eq!(c(317.0, "mOhm", "Ohm"), 0.317);
        assert_eq!(c(1.5, "kOhm", "Ohm"), 1500.0);
        assert_eq!(c(5.0, "mm", "m"), 0.005);
        assert_eq!(c(50.0, "ms", "s"), 0.05);
        assert_eq!(c(137.0, "mA", "A"), 0.137);
        assert_eq!(c(2.0, "kg", "kg"), 2.0);
        assert_eq!(c(250.0, "g", "kg"), 0.25);
    }

    #[test]
    fn listed_units() {
        assert_eq!(c(30.2, "mNm/A", "N.m/A"), 0.0302);
        assert_eq!(c(30.2, "mN.m/A", "N.m/A"), 0.0302);
        assert_eq!(c(142.0, "g.cm2", "kg.m2"), 1.42e-5);
        assert_eq!(c(1.5, "kg.cm2", "kg.m2"), 1.5e-4);
        assert_eq!(c(72.0, "%", "1"), 0.72);
        assert_eq!(c(25.0, "degC", "K"), 298.15);
        assert_eq!(c(298.15, "K", "degC"), 25.0);
        assert_eq!(c(1.0, "V.s/rad", "N.m/A"), 1.0);
        let w = c(60.0, "rpm", "rad/s");
        assert!((w - 2.0 * PI).abs() < 1e-12, "{w}");
        let k = c(2.107, "mV/rpm", "N.m/A");
        assert!((k - 0.020120).abs() < 1e-5, "{k}");
        let d = c(2.4e-4, "mNm/rpm", "N.m.s/rad");
        assert!((d - 2.2918e-6).abs() < 1e-9, "{d}");
        // Gear backlash: 60 arcmin = 1 deg.
        let b = c(60.0, "arcmin", "rad");
        assert!((b - PI / 180.0).abs() < 1e-15, "{b}");
    }

    #[test]
    fn identity_is_exact() {
        let x = 0.1 + 0.2;
        assert_eq!(c(x, "H", "H"), x);
        assert_eq!(c(x, "1", "1"), x);
    }

    #[test]
    fn incompatible_and_unknown_units_are_errors() {
        assert!(matches!(convert(1.0, "rpm", "H"), Err(UnitError::Incompatible { .. })));
        assert!(matches!(convert(1.0, "furlong", "m"), Err(UnitError::Unknown(_))));
        assert!(matches!(convert(1.0, "uH", "Ohm"), Err(UnitError::Incompatible { .. })));
    }

    #[test]
    fn si_units_are_their_own_si() {
        for u in si_units() {
            let l = lookup(u).expect("SI unit in the table");
            assert!(l.is_identity(), "{u}");
            assert!(is_si(l.si), "{u} -> {}", l.si);
        }
        assert!(!is_si("mH"));
        assert_eq!(si_of("mH"), Some("H"));
        assert_eq!(si_of("rpm"), Some("rad/s"));
    }
}
