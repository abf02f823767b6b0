//! JSON for people and programs: indented like `serde_json`'s pretty printer, but an array of
//! numbers, strings, booleans or nulls stays on one line (`"cg_world": [0.16, 0.019, -0.029]`).
//! A report of 2,000 bodies printed one number per line was 8.8 MB, most of it indentation; on
//! one line per vector it is about 40 % smaller, reads as the vectors it holds, and costs less
//! to write and to deflate. Any JSON reader reads it as before.

use std::io::{self, Write};

use serde::Serialize;
use serde_json::ser::{CompactFormatter, Formatter};

/// `value` as indented JSON, arrays of scalars on one line.
pub fn to_vec<T: Serialize + ?Sized>(value: &T) -> serde_json::Result<Vec<u8>> {
    let mut out = Vec::with_capacity(4096);
    let mut ser = serde_json::Serializer::with_formatter(&mut out, Readable::default());
    value.serialize(&mut ser)?;
    Ok(out)
}

/// `value` as [`to_vec`] writes it, as a string.
pub fn to_string<T: Serialize + ?Sized>(value: &T) -> serde_json::Result<String> {
    // serde_json writes only valid UTF-8: the bytes are taken as they are.
    to_vec(value).map(|v| String::from_utf8(v).unwrap_or_else(|e| String::from_utf8_lossy(e.as_bytes()).into_owned()))
}

/// An open array: whether its elements went on lines of their own (the first was an array or
/// an object), and how many it has so far.
struct Open {
    block: bool,
    len: usize,
}

#[derive(Default)]
struct Readable {
    indent: usize,
    /// Whether the innermost object has a member so far.
    has_member: bool,
    arrays: Vec<Open>,
    /// Set by `begin_array_value` (whether it is the first): the separator before the element,
    /// written once the element shows whether it is a scalar.
    pending: Option<bool>,
}

impl Readable {
    fn newline<W: ?Sized + Write>(&self, w: &mut W) -> io::Result<()> {
        w.write_all(b"\n")?;
        for _ in 0..self.indent {
            w.write_all(b"  ")?;
        }
        Ok(())
    }

    /// Before a value: the separator an array element still owes, on its own line when the
    /// array is laid out in lines (or becomes so, with a first element that is a container).
    fn value<W: ?Sized + Write>(&mut self, w: &mut W, container: bool) -> io::Result<()> {
        let Some(first) = self.pending.take() else { return Ok(()) };
        let block = match self.arrays.last_mut() {
            Some(open) => {
                if container && open.len == 0 {
                    open.block = true;
                }
                open.len += 1;
                open.block
            }
            None => container,
        };
        if block {
            if !first {
                w.write_all(b",")?;
            }
            self.newline(w)
        } else if first {
            Ok(())
        } else {
            w.write_all(b", ")
        }
    }
}

macro_rules! scalar {
    ($($name:ident: $t:ty),* $(,)?) => {
        $(fn $name<W: ?Sized + Write>(&mut self, w: &mut W, v: $t) -> io::Result<()> {
            self.value(w, false)?;
            CompactFormatter.$name(w, v)
        })*
    };
}

impl Formatter for Readable {
    scalar!(
        write_bool: bool, write_i8: i8, write_i16: i16, write_i32: i32, write_i64: i64, write_i128: i128,
        write_u8: u8, write_u16: u16, write_u32: u32, write_u64: u64, write_u128: u128, write_f32: f32, write_f64: f64,
    );

    fn write_null<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.value(w, false)?;
        w.write_all(b"null")
    }

    fn write_number_str<W: ?Sized + Write>(&mut self, w: &mut W, v: &str) -> io::Result<()> {
        self.value(w, false)?;
        w.write_all(v.as_bytes())
    }

    fn begin_string<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.value(w, false)?;
        w.write_all(b"\"")
    }

    fn write_raw_fragment<W: ?Sized + Write>(&mut self, w: &mut W, fragment: &str) -> io::Result<()> {
        self.value(w, false)?;
        w.write_all(fragment.as_bytes())
    }

    fn begin_array<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.value(w, true)?;
        self.indent += 1;
        self.arrays.push(Open { block: false, len: 0 });
        w.write_all(b"[")
    }

    fn begin_array_value<W: ?Sized + Write>(&mut self, _w: &mut W, first: bool) -> io::Result<()> {
        self.pending = Some(first);
        Ok(())
    }

    fn end_array_value<W: ?Sized + Write>(&mut self, _w: &mut W) -> io::Result<()> {
        Ok(())
    }

    fn end_array<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.indent -= 1;
        if self.arrays.pop().is_some_and(|open| open.block) {
            self.newline(w)?;
        }
        w.write_all(b"]")
    }

    fn begin_object<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.value(w, true)?;
        self.indent += 1;
        self.has_member = false;
        w.write_all(b"{")
    }

    fn begin_object_key<W: ?Sized + Write>(&mut self, w: &mut W, first: bool) -> io::Result<()> {
        if !first {
            w.write_all(b",")?;
        }
        self.newline(w)
    }

    fn begin_object_value<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        w.write_all(b": ")
    }

    fn end_object_value<W: ?Sized + Write>(&mut self, _w: &mut W) -> io::Result<()> {
        self.has_member = true;
        Ok(())
    }

    fn end_object<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.indent -= 1;
        if self.has_member {
            self.newline(w)?;
        }
        w.write_all(b"}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vectors_on_one_line_and_containers_indented() {
        let v = serde_json::json!({
            "name": "LINK_4",
            "cg": [0.16, 0.019, -0.029],
            "inertia": [[0.001, 0.0, 0.0], [0.0, 0.002, 0.0], [0.0, 0.0, 0.0025]],
            "geometry": ["a.stl", "b.stl"],
            "empty": [],
            "none": {},
            "frames": [{"name": "CG", "at": [1, 2, 3], "connector": null}, {"name": "CS2", "flags": [true, false]}],
        });
        let text = to_string(&v).expect("json");
        let expected = r#"{
  "cg": [0.16, 0.019, -0.029],
  "empty": [],
  "frames": [
    {
      "at": [1, 2, 3],
      "connector": null,
      "name": "CG"
    },
    {
      "flags": [true, false],
      "name": "CS2"
    }
  ],
  "geometry": ["a.stl", "b.stl"],
  "inertia": [
    [0.001, 0.0, 0.0],
    [0.0, 0.002, 0.0],
    [0.0, 0.0, 0.0025]
  ],
  "name": "LINK_4",
  "none": {}
}"#;
        assert_eq!(text, expected);
        let back: serde_json::Value = serde_json::from_str(&text).expect("reads back");
        assert_eq!(back, v);
    }

    #[test]
    fn any_value_reads_back_the_same() {
        // Nesting of every kind, escapes, and numbers at the edges.
        let v = serde_json::json!([
            [],
            [[]],
            [{}],
            [[1], [2, [3, [4]]]],
            {"a\"b\n": ["x\u{1}y", -0.0, 1e300, u64::MAX, i64::MIN]},
            [null, {"k": [{"z": []}]}],
            "top",
        ]);
        let text = to_vec(&v).expect("json");
        let back: serde_json::Value = serde_json::from_slice(&text).expect("reads back");
        assert_eq!(back, v);
        assert_eq!(to_string(&5).expect("json"), "5");
        assert_eq!(to_string(&Vec::<u8>::new()).expect("json"), "[]");
    }
}
