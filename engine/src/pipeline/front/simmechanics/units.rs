//! The unit table: every unit string the front end accepts and its factor to SI.
//!
//! Only the base factors (length and mass) are typed in; areas, volumes and inertias are
//! derived from them, so `lbm*in^2` is exactly `0.45359237 * 0.0254 * 0.0254` kg·m².
//! Unit strings are matched exactly (case-sensitive); anything else is an error listing the
//! accepted spellings.

/// Metres per inch (exact by definition).
pub(crate) const INCH: f64 = 0.0254;
/// Metres per foot (exact by definition).
pub(crate) const FOOT: f64 = 0.3048;
/// Kilograms per pound-mass (exact by definition).
pub(crate) const POUND: f64 = 0.45359237;
/// Kilograms per slug (1 lbf·s²/ft).
pub(crate) const SLUG: f64 = 14.5939029372;

/// Length units, metres per unit.
const LENGTH: [(&str, f64); 5] = [("mm", 1e-3), ("cm", 1e-2), ("m", 1.0), ("in", INCH), ("ft", FOOT)];

/// Mass units, kilograms per unit.
const MASS: [(&str, f64); 4] = [("kg", 1.0), ("g", 1e-3), ("lbm", POUND), ("slug", SLUG)];

/// Angle units, radians per unit.
const ANGLE: [(&str, f64); 2] = [("rad", 1.0), ("deg", std::f64::consts::PI / 180.0)];

/// Area units: (spelling, length unit squared).
const AREA: [(&str, &str); 5] = [("mm^2", "mm"), ("cm^2", "cm"), ("m^2", "m"), ("in^2", "in"), ("ft^2", "ft")];

/// Volume units: (spelling, length unit cubed).
const VOLUME: [(&str, &str); 5] = [("mm^3", "mm"), ("cm^3", "cm"), ("m^3", "m"), ("in^3", "in"), ("ft^3", "ft")];

/// Inertia units: (spelling, mass unit, length unit squared).
const INERTIA: [(&str, &str, &str); 9] = [
    ("kg*m^2", "kg", "m"),
    ("kg*cm^2", "kg", "cm"),
    ("kg*mm^2", "kg", "mm"),
    ("g*cm^2", "g", "cm"),
    ("g*mm^2", "g", "mm"),
    ("lbm*in^2", "lbm", "in"),
    ("lbm*ft^2", "lbm", "ft"),
    ("slug*in^2", "slug", "in"),
    ("slug*ft^2", "slug", "ft"),
];

/// A physical quantity whose unit the XML states.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Quantity {
    Length,
    Mass,
    Inertia,
    Volume,
    Area,
    Angle,
}

impl Quantity {
    /// Lower-case name for messages.
    pub fn name(self) -> &'static str {
        match self {
            Quantity::Length => "length",
            Quantity::Mass => "mass",
            Quantity::Inertia => "inertia",
            Quantity::Volume => "volume",
            Quantity::Area => "area",
            Quantity::Angle => "angle",
        }
    }

    /// The accepted spellings, for messages (kept in sync with the tables by a test).
    pub fn allowed(self) -> &'static str {
        match self {
            Quantity::Length => "mm, cm, m, in, ft",
            Quantity::Mass => "kg, g, lbm, slug",
            Quantity::Inertia => "kg*m^2, kg*cm^2, kg*mm^2, g*cm^2, g*mm^2, lbm*in^2, lbm*ft^2, slug*in^2, slug*ft^2",
            Quantity::Volume => "mm^3, cm^3, m^3, in^3, ft^3",
            Quantity::Area => "mm^2, cm^2, m^2, in^2, ft^2",
            Quantity::Angle => "rad, deg",
        }
    }

    /// SI factor of `unit` (value_SI = value * factor), `None` when unknown.
    pub fn factor(self, unit: &str) -> Option<f64> {
        match self {
            Quantity::Length => lookup(&LENGTH, unit),
            Quantity::Mass => lookup(&MASS, unit),
            Quantity::Angle => lookup(&ANGLE, unit),
            Quantity::Area => {
                let (_, len) = AREA.iter().find(|(s, _)| *s == unit)?;
                let l = lookup(&LENGTH, len)?;
                Some(l * l)
            }
            Quantity::Volume => {
                let (_, len) = VOLUME.iter().find(|(s, _)| *s == unit)?;
                let l = lookup(&LENGTH, len)?;
                Some(l * l * l)
            }
            Quantity::Inertia => {
                let (_, mass, len) = INERTIA.iter().find(|(s, _, _)| *s == unit)?;
                let m = lookup(&MASS, mass)?;
                let l = lookup(&LENGTH, len)?;
                Some(m * (l * l))
            }
        }
    }
}

fn lookup(table: &[(&str, f64)], unit: &str) -> Option<f64> {
    table.iter().find(|(s, _)| *s == unit).map(|&(_, f)| f)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spellings(q: Quantity) -> Vec<&'static str> {
        match q {
            Quantity::Length => LENGTH.iter().map(|u| u.0).collect(),
            Quantity::Mass => MASS.iter().map(|u| u.0).collect(),
            Quantity::Angle => ANGLE.iter().map(|u| u.0).collect(),
            Quantity::Area => AREA.iter().map(|u| u.0).collect(),
            Quantity::Volume => VOLUME.iter().map(|u| u.0).collect(),
            Quantity::Inertia => INERTIA.iter().map(|u| u.0).collect(),
        }
    }

    #[test]
    fn allowed_lists_match_tables_and_all_resolve() {
        use Quantity::*;
        for q in [Length, Mass, Inertia, Volume, Area, Angle] {
            let names = spellings(q);
            assert_eq!(q.allowed(), names.join(", "), "{q:?}");
            for n in names {
                assert!(q.factor(n).is_some_and(|f| f > 0.0), "{q:?} {n}");
            }
        }
    }

    #[test]
    fn exact_imperial_factors() {
        assert_eq!(Quantity::Length.factor("in"), Some(0.0254));
        assert_eq!(Quantity::Length.factor("ft"), Some(0.3048));
        assert_eq!(Quantity::Mass.factor("lbm"), Some(0.45359237));
        assert_eq!(Quantity::Mass.factor("slug"), Some(14.5939029372));
        assert_eq!(Quantity::Inertia.factor("lbm*in^2"), Some(0.45359237 * (0.0254 * 0.0254)));
        assert_eq!(Quantity::Volume.factor("in^3"), Some(0.0254 * 0.0254 * 0.0254));
        assert_eq!(Quantity::Area.factor("mm^2"), Some(1e-3 * 1e-3));
        assert_eq!(Quantity::Inertia.factor("kg*m^2"), Some(1.0));
        assert_eq!(Quantity::Length.factor("furlong"), None);
        assert_eq!(Quantity::Length.factor("MM"), None);
    }
}
