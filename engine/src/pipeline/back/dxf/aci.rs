//! The AutoCAD Color Index (ACI) palette: the RGB colour of indices 1..=255.
//!
//! The palette follows a fixed scheme:
//! - 1..=7: red, yellow, green, cyan, blue, magenta, white (7 shows black on a light background);
//!   8 and 9: dark and light grey (128 and 192).
//! - 10..=249: 24 hues in 15° steps (10 = red, 50 = yellow, 90 = green, 130 = cyan, 170 = blue,
//!   210 = magenta), ten entries a hue: five brightness levels (255, 204, 153, 127, 76), each as the
//!   full colour (even index) and as a pale version whose weakest channel is half the level (odd
//!   index). Channels in between are interpolated linearly along the hue circle and rounded down,
//!   as in the HSV model.
//! - 250..=255: greys from 51 to 255 in six equal steps, rounded down.

/// Brightness levels of the hue blocks, in index order.
const LEVELS: [u32; 5] = [255, 204, 153, 127, 76];

/// RGB of ACI `index`; `None` for 0 (BYBLOCK).
pub fn rgb(index: u8) -> Option<[u8; 3]> {
    let i = u32::from(index);
    let c = match i {
        0 => return None,
        1 => [255, 0, 0],
        2 => [255, 255, 0],
        3 => [0, 255, 0],
        4 => [0, 255, 255],
        5 => [0, 0, 255],
        6 => [255, 0, 255],
        7 => [255, 255, 255],
        8 => [128, 128, 128],
        9 => [192, 192, 192],
        10..=249 => {
            let k = i - 10;
            let hue = (k / 10) * 15; // degrees
            let shade = k % 10;
            let v = LEVELS[(shade / 2) as usize];
            let m = if shade % 2 == 1 { v / 2 } else { 0 };
            // Channel ramp: t in 0..=60 degrees from `m` (t = 0) to `v` (t = 60), rounded down.
            let ramp = |t: u32| (m + (v - m) * t / 60) as u8;
            let (vb, mb) = (v as u8, m as u8);
            let f = hue % 60;
            match hue / 60 {
                0 => [vb, ramp(f), mb],
                1 => [ramp(60 - f), vb, mb],
                2 => [mb, vb, ramp(f)],
                3 => [mb, ramp(60 - f), vb],
                4 => [ramp(f), mb, vb],
                _ => [vb, mb, ramp(60 - f)],
            }
        }
        _ => {
            let g = (51 + (i - 250) * 204 / 5) as u8;
            [g, g, g]
        }
    };
    Some(c)
}

/// The ACI palette entries that are greys (white included).
const GREYS: [u8; 9] = [7, 8, 9, 250, 251, 252, 253, 254, 255];

/// The ACI index (1..=255) whose palette colour is nearest to `rgb` (Euclidean distance in RGB;
/// ties go to the lower index, so pure red is 1 rather than 10).
///
/// Greys (channels within 16 of each other) only match grey entries: the hue blocks hold very dark
/// saturated colours (76, 0, 0) that are nearer to black than the darkest grey in plain RGB
/// distance, and a black part should not turn dark red. So black maps to 250 (the darkest grey)
/// and white to 7.
pub fn nearest_aci(rgb: [u8; 3]) -> u8 {
    let (lo, hi) = (rgb.iter().min().copied().unwrap_or(0), rgb.iter().max().copied().unwrap_or(0));
    let dist = |i: u8| self::rgb(i).map_or(u32::MAX, |c| (0..3).map(|k| (i32::from(c[k]) - i32::from(rgb[k])).pow(2) as u32).sum());
    let best = |candidates: &mut dyn Iterator<Item = u8>| candidates.min_by_key(|&i| (dist(i), i)).unwrap_or(7);
    if hi - lo <= 16 {
        best(&mut GREYS.iter().copied())
    } else {
        best(&mut (1..=255u8))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Entries of the widely published ACI table, as spot checks of the derivation.
    #[test]
    fn matches_published_entries() {
        let known: [(u8, [u8; 3]); 24] = [
            (1, [255, 0, 0]),
            (8, [128, 128, 128]),
            (9, [192, 192, 192]),
            (10, [255, 0, 0]),
            (11, [255, 127, 127]),
            (12, [204, 0, 0]),
            (13, [204, 102, 102]),
            (16, [127, 0, 0]),
            (17, [127, 63, 63]),
            (19, [76, 38, 38]),
            (20, [255, 63, 0]),
            (21, [255, 159, 127]),
            (25, [153, 95, 76]),
            (26, [127, 31, 0]),
            (35, [153, 114, 76]),
            (43, [204, 178, 102]),
            (45, [153, 133, 76]),
            (49, [76, 66, 38]),
            (50, [255, 255, 0]),
            (60, [191, 255, 0]),
            (250, [51, 51, 51]),
            (251, [91, 91, 91]),
            (252, [132, 132, 132]),
            (254, [214, 214, 214]),
        ];
        for (i, c) in known {
            assert_eq!(rgb(i), Some(c), "ACI {i}");
        }
        assert_eq!(rgb(255), Some([255, 255, 255]));
        assert_eq!(rgb(0), None);
        assert_eq!(rgb(90), Some([0, 255, 0]));
        assert_eq!(rgb(130), Some([0, 255, 255]));
        assert_eq!(rgb(170), Some([0, 0, 255]));
        assert_eq!(rgb(210), Some([255, 0, 255]));
    }

    #[test]
    fn nearest() {
        assert_eq!(nearest_aci([255, 0, 0]), 1);
        assert_eq!(nearest_aci([255, 255, 0]), 2);
        assert_eq!(nearest_aci([0, 255, 0]), 3);
        assert_eq!(nearest_aci([0, 0, 255]), 5);
        assert_eq!(nearest_aci([255, 255, 255]), 7);
        assert_eq!(nearest_aci([0, 0, 0]), 250);
        assert_eq!(nearest_aci([128, 128, 128]), 8);
        assert_eq!(nearest_aci([179, 179, 179]), 253);
        assert_eq!(nearest_aci([204, 0, 0]), 12);
        assert_eq!(nearest_aci([250, 130, 125]), 11);
        for i in 1..=255u8 {
            let c = rgb(i).expect("palette");
            assert_eq!(rgb(nearest_aci(c)), Some(c), "ACI {i} maps to an entry of the same colour");
        }
    }
}
