//! The MATLAB v4 "trajectory" result files Dymola and OpenModelica write (`dsres.mat`,
//! `<Model>_res.mat`), read from bytes in memory without converting the data: the matrices are
//! located once, names and descriptions decoded, and a variable's series is read from its
//! column when asked. No IO, no panics on input.
//!
//! Layout (facts in `shared/guides/results-motion-collision.md`):
//! - each matrix: five 32-bit integers (type `MOPT`, rows, columns, imaginary flag, name length
//!   with its NUL), the name, then the elements column by column; `M` 0 little-endian, 1
//!   big-endian; `P` the element type (0 f64, 1 f32, 2 i32, 3 i16, 4 u16, 5 u8); `T` 1 text;
//! - `Aclass` (`Atrajectory`, `1.1`, -, `binTrans`|`binNormal`), then `name`, `description`,
//!   `dataInfo`, `data_1`, `data_2`; with `binTrans` every matrix is stored transposed (a name per
//!   column, a time instant per column of `data_2`);
//! - `dataInfo` per variable: block (1 = `data_1`, 2 = `data_2`, 0 = the time axis), 1-based
//!   column (negative: the negated column), interpolation, extrapolation;
//! - the old Dymola "export as plotted" variant: `Aclass` version 1.0 with `names` and `data`
//!   (a time instant per row; the first column is time).
//!
//! Names are kept as written and also found in the other tool's spelling ([`canonical`]:
//! `R.T[1, 1]` and `R.T[1,1]`, `a.b.der(c)` and `der(a.b.c)`).

use std::collections::HashMap;

/// Why a file cannot be read.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum MatError {
    #[error("{file}: this is a MATLAB v5 (or later) MAT-file, not the MATLAB v4 result format Dymola and OpenModelica write (save results as MAT v4 / dsres.mat)")]
    MatlabV5 { file: String },
    #[error("{file}: a linearisation result (Aclass \"AlinearSystem\": A, B, C, D matrices), not a simulation trajectory")]
    Linearisation { file: String },
    #[error("{file}: not a simulation result: {what}")]
    NotATrajectory { file: String, what: String },
    #[error("{file}: matrix \"{matrix}\" at byte {offset}: {what}")]
    BadMatrix { file: String, matrix: String, offset: usize, what: String },
    #[error("{file}: truncated: matrix \"{matrix}\" at byte {offset} needs {needed} bytes, {left} are left")]
    Truncated { file: String, matrix: String, offset: usize, needed: usize, left: usize },
    #[error("{file}: variable \"{name}\": {what}")]
    BadVariable { file: String, name: String, what: String },
    #[error("{file}: matrix \"{matrix}\" row {row}, column {column} holds {value} ({what}); results must be finite")]
    NonFinite { file: String, matrix: String, row: usize, column: usize, value: String, what: String },
}

/// Element type of a matrix.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Elem {
    F64,
    F32,
    I32,
    I16,
    U16,
    U8,
}

impl Elem {
    fn size(self) -> usize {
        match self {
            Elem::F64 => 8,
            Elem::F32 | Elem::I32 => 4,
            Elem::I16 | Elem::U16 => 2,
            Elem::U8 => 1,
        }
    }
}

/// One matrix located in the file: its elements are read on demand.
#[derive(Clone, Debug)]
struct Matrix {
    name: String,
    rows: usize,
    cols: usize,
    elem: Elem,
    big_endian: bool,
    /// Byte offset of the first element.
    start: usize,
}

impl Matrix {
    /// Element `(r, c)` (column-major storage), as f64. Indices must be in range.
    fn get(&self, bytes: &[u8], r: usize, c: usize) -> f64 {
        let i = c * self.rows + r;
        let at = self.start + i * self.elem.size();
        let b = &bytes[at..at + self.elem.size()];
        macro_rules! rd {
            ($t:ty, $n:expr) => {{
                let mut a = [0u8; $n];
                a.copy_from_slice(b);
                if self.big_endian {
                    <$t>::from_be_bytes(a)
                } else {
                    <$t>::from_le_bytes(a)
                }
            }};
        }
        match self.elem {
            Elem::F64 => rd!(f64, 8),
            Elem::F32 => f64::from(rd!(f32, 4)),
            Elem::I32 => f64::from(rd!(i32, 4)),
            Elem::I16 => f64::from(rd!(i16, 2)),
            Elem::U16 => f64::from(rd!(u16, 2)),
            Elem::U8 => f64::from(b[0]),
        }
    }

    /// Text rows (one string per row; `by_columns`: one per column), bytes decoded as UTF-8 with
    /// a Latin-1 fallback, trailing NULs and spaces removed.
    fn strings(&self, bytes: &[u8], by_columns: bool) -> Vec<String> {
        let (count, len) = if by_columns { (self.cols, self.rows) } else { (self.rows, self.cols) };
        // A matrix without elements holds no text, whatever count its other dimension claims
        // (with elements, the count is bounded by the bytes the file holds).
        if count == 0 || len == 0 {
            return Vec::new();
        }
        (0..count)
            .map(|k| {
                let raw: Vec<u8> = (0..len)
                    .map(|j| {
                        let v = if by_columns { self.get(bytes, j, k) } else { self.get(bytes, k, j) };
                        if (0.0..=255.0).contains(&v) {
                            v as u8
                        } else {
                            b'?'
                        }
                    })
                    .collect();
                let end = raw.iter().rposition(|b| *b != 0 && *b != b' ').map_or(0, |p| p + 1);
                let raw = &raw[..end];
                match std::str::from_utf8(raw) {
                    Ok(s) => s.to_string(),
                    Err(_) => raw.iter().map(|b| char::from(*b)).collect(),
                }
            })
            .collect()
    }
}

/// Reads the matrix headers one after the other.
fn next_matrix(bytes: &[u8], at: &mut usize, file: &str) -> Result<Option<Matrix>, MatError> {
    if *at >= bytes.len() {
        return Ok(None);
    }
    let offset = *at;
    let trunc = |needed: usize, matrix: &str| MatError::Truncated {
        file: file.into(),
        matrix: matrix.into(),
        offset,
        needed,
        left: bytes.len() - offset,
    };
    if bytes.len() - offset < 20 {
        return Err(trunc(20, "?"));
    }
    let word = |k: usize, be: bool| {
        let mut a = [0u8; 4];
        a.copy_from_slice(&bytes[offset + 4 * k..offset + 4 * k + 4]);
        if be {
            i32::from_be_bytes(a)
        } else {
            i32::from_le_bytes(a)
        }
    };
    // The type code decides the byte order: read it little-endian first.
    let mut be = false;
    let mut ty = word(0, false);
    if !(0..10_000).contains(&ty) {
        ty = word(0, true);
        be = true;
    }
    let bad = |what: String| MatError::BadMatrix { file: file.into(), matrix: "?".into(), offset, what };
    if !(0..10_000).contains(&ty) {
        return Err(bad(format!("type code {} is not a MATLAB v4 type", word(0, false))));
    }
    let (m, o, p, t) = (ty / 1000, (ty / 100) % 10, (ty / 10) % 10, ty % 10);
    if m > 1 || o != 0 || t > 2 {
        return Err(bad(format!("type code {ty:04} is not a MATLAB v4 type (MOPT)")));
    }
    if (m == 1) != be {
        return Err(bad(format!("type code {ty:04} does not match the byte order")));
    }
    let elem = match p {
        0 => Elem::F64,
        1 => Elem::F32,
        2 => Elem::I32,
        3 => Elem::I16,
        4 => Elem::U16,
        5 => Elem::U8,
        _ => return Err(bad(format!("element type {p} is not a MATLAB v4 type"))),
    };
    let (rows, cols, imag, namlen) = (word(1, be), word(2, be), word(3, be), word(4, be));
    if rows < 0 || cols < 0 || !(1..=4096).contains(&namlen) {
        return Err(bad(format!("size {rows} x {cols} or name length {namlen} is impossible")));
    }
    let name_start = offset + 20;
    let name_end = name_start + namlen as usize;
    if name_end > bytes.len() {
        return Err(trunc(20 + namlen as usize, "?"));
    }
    let name_raw = &bytes[name_start..name_end];
    let name: String = String::from_utf8_lossy(name_raw.split(|b| *b == 0).next().unwrap_or_default()).into_owned();
    if imag != 0 {
        return Err(MatError::BadMatrix { file: file.into(), matrix: name, offset, what: "complex matrices are not results".into() });
    }
    let (rows, cols) = (rows as usize, cols as usize);
    let count = rows.checked_mul(cols).and_then(|n| n.checked_mul(elem.size()));
    let Some(size) = count else {
        return Err(MatError::BadMatrix { file: file.into(), matrix: name, offset, what: format!("size {rows} x {cols} overflows") });
    };
    if name_end + size > bytes.len() {
        return Err(trunc(20 + namlen as usize + size, &name));
    }
    *at = name_end + size;
    Ok(Some(Matrix { name, rows, cols, elem, big_endian: be, start: name_end }))
}

/// Where a variable's values are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Source {
    /// Constant over the run (`data_1`, column).
    Constant(usize),
    /// A column of `data_2` (the time column is 0).
    Series(usize),
}

/// A variable of a result.
#[derive(Clone, Debug, PartialEq)]
pub struct Variable {
    pub name: String,
    pub description: String,
    pub source: Source,
    /// A negated alias of its column.
    pub negated: bool,
}

impl Variable {
    /// The unit from a description's `[unit]` suffix, as Dymola and OpenModelica write it.
    pub fn unit(&self) -> &str {
        let d = self.description.trim_end();
        match (d.ends_with(']'), d.rfind('[')) {
            (true, Some(i)) => &d[i + 1..d.len() - 1],
            _ => "",
        }
    }
}

/// A result file: its variables and its data, read on demand.
#[derive(Debug)]
pub struct Trajectory<'a> {
    bytes: &'a [u8],
    pub variables: Vec<Variable>,
    index: HashMap<String, usize>,
    data_1: Option<Matrix>,
    data_2: Matrix,
    /// `binTrans`: a variable per row of the stored `data_k`, a time instant per column.
    transposed: bool,
    /// `Aclass` version 1.0 (`names` + `data`).
    pub old_format: bool,
    /// Element type of `data_2`: 4 for float32 (Dymola), 8 for float64.
    pub precision_bytes: usize,
}

/// The spelling both tools' names are found by: no spaces after commas inside brackets and
/// `der(a.b.c)` for Dymola's `a.b.der(c)`.
pub fn canonical(name: &str) -> String {
    let mut s = String::with_capacity(name.len());
    let mut depth = 0usize;
    let mut after_comma = false;
    for ch in name.chars() {
        match ch {
            '[' => depth += 1,
            ']' => depth = depth.saturating_sub(1),
            _ => {}
        }
        if depth > 0 && after_comma && ch == ' ' {
            continue;
        }
        after_comma = depth > 0 && ch == ',';
        s.push(ch);
    }
    // a.b.der(c) -> der(a.b.c)
    if let Some(i) = s.find(".der(") {
        if s.ends_with(')') && !s.starts_with("der(") {
            let inner = &s[i + 5..s.len() - 1];
            return format!("der({}.{inner})", &s[..i]);
        }
    }
    s
}

impl<'a> Trajectory<'a> {
    /// Reads a result file (`file` names it in errors).
    pub fn read(bytes: &'a [u8], file: &str) -> Result<Trajectory<'a>, MatError> {
        if bytes.len() >= 116 && bytes.starts_with(b"MATLAB") && !bytes[..116].contains(&0) {
            return Err(MatError::MatlabV5 { file: file.into() });
        }
        let mut at = 0;
        let mut matrices: Vec<Matrix> = Vec::new();
        while let Some(m) = next_matrix(bytes, &mut at, file)? {
            matrices.push(m);
            if matrices.len() > 64 {
                break;
            }
        }
        let find = |name: &str| matrices.iter().find(|m| m.name == name);
        let not = |what: &str| MatError::NotATrajectory { file: file.into(), what: what.into() };
        let aclass = find("Aclass").ok_or_else(|| not("it has no \"Aclass\" matrix"))?;
        // Aclass is text, a string per row (never transposed in the files seen); a writer that
        // stored it a string per column is read too.
        let rows = aclass.strings(bytes, false);
        let cols = aclass.strings(bytes, true);
        let known = |l: &[String]| l.first().is_some_and(|s| s == "Atrajectory" || s == "AlinearSystem");
        let lines = if known(&rows) || !known(&cols) { rows } else { cols };
        let kind = lines.first().cloned().unwrap_or_default();
        if kind == "AlinearSystem" {
            return Err(MatError::Linearisation { file: file.into() });
        }
        if kind != "Atrajectory" {
            return Err(not(&format!("Aclass is \"{kind}\", not \"Atrajectory\"")));
        }
        let version = lines.get(1).cloned().unwrap_or_default();
        let transposed = lines.get(3).is_some_and(|s| s == "binTrans");
        if version == "1.0" {
            return Self::read_old(bytes, file, &matrices);
        }
        if version != "1.1" {
            return Err(not(&format!("trajectory version \"{version}\" (1.0 and 1.1 are known)")));
        }
        let name_m = find("name").ok_or_else(|| not("no \"name\" matrix"))?;
        let names = name_m.strings(bytes, transposed);
        let descriptions = find("description").map(|d| d.strings(bytes, transposed)).unwrap_or_default();
        let info = find("dataInfo").ok_or_else(|| not("no \"dataInfo\" matrix"))?;
        let data_1 = find("data_1").cloned();
        let data_2 = find("data_2").cloned().ok_or_else(|| not("no \"data_2\" matrix (no time series)"))?;
        let n = names.len();
        let (info_vars, info_fields) = if transposed { (info.cols, info.rows) } else { (info.rows, info.cols) };
        if info_vars != n || info_fields < 2 {
            return Err(not(&format!("dataInfo describes {info_vars} variables with {info_fields} fields; name has {n}")));
        }
        let (d2_vars, _) = if transposed { (data_2.rows, data_2.cols) } else { (data_2.cols, data_2.rows) };
        // Columns of data_1 a constant can be read from (none when it has no time instant).
        let d1_vars = data_1.as_ref().filter(|d| d.rows > 0 && d.cols > 0).map_or(0, |d| if transposed { d.rows } else { d.cols });
        let mut variables = Vec::with_capacity(n);
        for (k, name) in names.into_iter().enumerate() {
            let field = |j: usize| if transposed { info.get(bytes, j, k) } else { info.get(bytes, k, j) };
            let (block, col) = (field(0) as i64, field(1) as i64);
            let negated = col < 0;
            let c = col.unsigned_abs() as usize;
            let bad = |what: String| MatError::BadVariable { file: file.into(), name: name.clone(), what };
            let source = match block {
                0 => Source::Series(0),
                1 if (1..=d1_vars).contains(&c) => Source::Constant(c - 1),
                2 if (1..=d2_vars).contains(&c) => Source::Series(c - 1),
                1 | 2 => return Err(bad(format!("column {col} of data_{block} does not exist"))),
                _ => return Err(bad(format!("data block {block} is unknown (0, 1 or 2)"))),
            };
            let description = descriptions.get(k).cloned().unwrap_or_default();
            variables.push(Variable { name, description, source, negated });
        }
        let precision_bytes = data_2.elem.size();
        Ok(Self::finish(bytes, variables, data_1, data_2, transposed, false, precision_bytes))
    }

    fn read_old(bytes: &'a [u8], file: &str, matrices: &[Matrix]) -> Result<Trajectory<'a>, MatError> {
        let not = |what: &str| MatError::NotATrajectory { file: file.into(), what: what.into() };
        let names_m = matrices.iter().find(|m| m.name == "names").ok_or_else(|| not("version 1.0 without \"names\""))?;
        let data = matrices.iter().find(|m| m.name == "data").ok_or_else(|| not("version 1.0 without \"data\""))?;
        let names = names_m.strings(bytes, false);
        if names.len() != data.cols {
            return Err(not(&format!("{} names for {} data columns", names.len(), data.cols)));
        }
        let variables = names
            .into_iter()
            .enumerate()
            .map(|(k, name)| Variable { name, description: String::new(), source: Source::Series(k), negated: false })
            .collect();
        let precision_bytes = data.elem.size();
        Ok(Self::finish(bytes, variables, None, data.clone(), false, true, precision_bytes))
    }

    fn finish(
        bytes: &'a [u8],
        variables: Vec<Variable>,
        data_1: Option<Matrix>,
        data_2: Matrix,
        transposed: bool,
        old_format: bool,
        precision_bytes: usize,
    ) -> Trajectory<'a> {
        let mut index = HashMap::with_capacity(variables.len() * 2);
        for (k, v) in variables.iter().enumerate() {
            index.entry(v.name.clone()).or_insert(k);
            index.entry(canonical(&v.name)).or_insert(k);
        }
        Trajectory { bytes, variables, index, data_1, data_2, transposed, old_format, precision_bytes }
    }

    /// Number of time instants (0 when `data_2` has no time column).
    pub fn len(&self) -> usize {
        let (vars, times) = if self.transposed { (self.data_2.rows, self.data_2.cols) } else { (self.data_2.cols, self.data_2.rows) };
        if vars == 0 {
            0
        } else {
            times
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// A variable by name in either tool's spelling.
    pub fn find(&self, name: &str) -> Option<usize> {
        self.index.get(name).or_else(|| self.index.get(&canonical(name))).copied()
    }

    /// The time axis.
    pub fn time(&self) -> Vec<f64> {
        (0..self.len()).map(|i| self.series_at(0, i)).collect()
    }

    fn series_at(&self, col: usize, i: usize) -> f64 {
        if self.transposed {
            self.data_2.get(self.bytes, col, i)
        } else {
            self.data_2.get(self.bytes, i, col)
        }
    }

    /// Value of variable `v` at time instant `i`.
    pub fn value(&self, v: usize, i: usize) -> f64 {
        let var = &self.variables[v];
        let x = match var.source {
            Source::Series(c) => self.series_at(c, i),
            Source::Constant(c) => match &self.data_1 {
                Some(d) if self.transposed => d.get(self.bytes, c, 0),
                Some(d) => d.get(self.bytes, 0, c),
                None => f64::NAN,
            },
        };
        if var.negated {
            -x
        } else {
            x
        }
    }

    /// The first non-finite value of the data matrices (`data_1`, then `data_2`; rows and
    /// columns counted from 1 as stored), naming the variable and time instant it belongs to.
    pub fn check_finite(&self, file: &str) -> Result<(), MatError> {
        let blocks = [(self.data_1.as_ref(), true), (Some(&self.data_2), false)];
        for (m, constant) in blocks.into_iter().filter_map(|(m, c)| m.map(|m| (m, c))) {
            if !matches!(m.elem, Elem::F64 | Elem::F32) {
                continue;
            }
            for c in 0..m.cols {
                for r in 0..m.rows {
                    let x = m.get(self.bytes, r, c);
                    if x.is_finite() {
                        continue;
                    }
                    let (var, instant) = if self.transposed { (r, c) } else { (c, r) };
                    let name = self
                        .variables
                        .iter()
                        .find(|v| if constant { v.source == Source::Constant(var) } else { v.source == Source::Series(var) })
                        .map_or_else(|| "no variable".to_string(), |v| format!("variable \"{}\"", crate::pipeline::ir::clip(&v.name, 200)));
                    let what = if constant { name } else { format!("{name} at time instant {}", instant + 1) };
                    return Err(MatError::NonFinite {
                        file: file.into(),
                        matrix: m.name.clone(),
                        row: r + 1,
                        column: c + 1,
                        value: format!("{x}"),
                        what,
                    });
                }
            }
        }
        Ok(())
    }

    /// The whole series of variable `v`.
    pub fn series(&self, v: usize) -> Vec<f64> {
        (0..self.len()).map(|i| self.value(v, i)).collect()
    }
}

#[cfg(test)]
mod tests;
