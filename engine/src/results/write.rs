//! Writes MAT v4 trajectory files (binTrans, as Dymola and OpenModelica write them): results
//! made by us (e.g. a motion's samples) that any tool reading simulation results opens, and
//! test inputs. The reader is [`super::mat`].

/// One matrix, little-endian: `p` element type (0 f64, 1 f32, 2 i32, 5 u8), `text` flag.
pub fn matrix(out: &mut Vec<u8>, name: &str, p: i32, text: bool, rows: usize, cols: usize, data: &[f64]) {
    let ty = p * 10 + i32::from(text);
    for w in [ty, rows as i32, cols as i32, 0, name.len() as i32 + 1] {
        out.extend_from_slice(&w.to_le_bytes());
    }
    out.extend_from_slice(name.as_bytes());
    out.push(0);
    for x in data {
        match p {
            0 => out.extend_from_slice(&x.to_le_bytes()),
            1 => out.extend_from_slice(&(*x as f32).to_le_bytes()),
            2 => out.extend_from_slice(&(*x as i32).to_le_bytes()),
            _ => out.push(*x as u8),
        }
    }
}

/// Text, a string per column (name, description of binTrans files).
pub fn text_cols(out: &mut Vec<u8>, name: &str, strings: &[&str]) {
    let len = strings.iter().map(|s| s.len()).max().unwrap_or(0);
    let mut data = Vec::new();
    for s in strings {
        let mut b: Vec<f64> = s.bytes().map(f64::from).collect();
        b.resize(len, 0.0);
        data.extend(b);
    }
    matrix(out, name, 5, true, len, strings.len(), &data);
}

/// Text, a string per row (Aclass).
pub fn text_rows(out: &mut Vec<u8>, name: &str, strings: &[&str]) {
    let len = strings.iter().map(|s| s.len()).max().unwrap_or(0);
    let mut data = vec![0.0; len * strings.len()];
    for (r, s) in strings.iter().enumerate() {
        for (c, b) in s.bytes().enumerate() {
            data[c * strings.len() + r] = f64::from(b);
        }
    }
    matrix(out, name, 5, true, strings.len(), len, &data);
}

/// A whole result: `series[k]` over `time` (float32 when `f32`), every variable in `data_2`.
pub fn trajectory(time: &[f64], series: &[(String, Vec<f64>)], f32: bool) -> Vec<u8> {
    let mut f = Vec::new();
    text_rows(&mut f, "Aclass", &["Atrajectory", "1.1", "", "binTrans"]);
    let mut names: Vec<&str> = vec!["time"];
    names.extend(series.iter().map(|(n, _)| n.as_str()));
    text_cols(&mut f, "name", &names);
    let desc: Vec<&str> = names.iter().map(|_| "").collect();
    text_cols(&mut f, "description", &desc);
    let mut info = vec![0.0, 1.0, 0.0, -1.0];
    for k in 0..series.len() {
        info.extend([2.0, (k + 2) as f64, 0.0, -1.0]);
    }
    matrix(&mut f, "dataInfo", 2, false, 4, names.len(), &info);
    matrix(&mut f, "data_1", 0, false, 1, 2, &[time[0], time[time.len() - 1]]);
    let mut d2 = Vec::with_capacity(time.len() * names.len());
    for (i, t) in time.iter().enumerate() {
        d2.push(*t);
        for (_, s) in series {
            d2.push(s[i]);
        }
    }
    matrix(&mut f, "data_2", if f32 { 1 } else { 0 }, false, names.len(), time.len(), &d2);
    f
}
