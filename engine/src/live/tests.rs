use super::*;

const MODEL: [u8; 16] = [0x12, 0x3e, 0x45, 0x67, 0xe8, 0x9b, 0x12, 0xd3, 0xa4, 0x56, 0x42, 0x66, 0x14, 0x17, 0x40, 0x00];

/// [`encode`] with the header's fields in line.
#[allow(clippy::too_many_arguments)]
fn enc(
    model: [u8; 16],
    version: u32,
    layout: [u8; 8],
    run: u32,
    seq: u32,
    time: f64,
    bodies: &[[f64; 12]],
    last: bool,
    token: Option<&str>,
) -> Vec<u8> {
    encode(&Header { model, version, layout, run, seq, time, last }, bodies, token)
}

fn identity_at(x: f64) -> [f64; 12] {
    [x, 2.0, 3.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]
}

#[test]
fn a_frame_reads_back() {
    let d = enc(MODEL, 3, [1, 2, 3, 4, 5, 6, 7, 8], 99, 7, 1.25, &[identity_at(1.0), identity_at(2.0)], true, None);
    assert_eq!(d.len(), HEADER + 2 * BODY);
    let f = decode(&d).expect("decodes");
    assert_eq!((f.version, f.seq, f.run, f.time, f.body_count(), f.is_final()), (3, 7, 99, 1.25, 2, true));
    assert_eq!(f.model_id(), "123e4567-e89b-12d3-a456-426614174000");
    assert_eq!(f.layout, [1, 2, 3, 4, 5, 6, 7, 8]);
    assert!(f.tag.is_none());
    let mut p = Vec::new();
    poses_into(&f, &mut p).expect("poses");
    assert_eq!(p, vec![1.0, 2.0, 3.0, 0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 3.0, 0.0, 0.0, 0.0, 1.0]);
}

#[test]
fn each_defect_has_its_reason() {
    let good = enc(MODEL, 3, [0; 8], 1, 0, 0.0, &[identity_at(1.0)], false, None);
    assert!(decode(&good).is_ok());
    assert_eq!(decode(&good[..63]).err(), Some(Drop::Malformed));
    assert_eq!(decode(b"").err(), Some(Drop::Malformed));
    let mut d = good.clone();
    d[0] = b'X';
    assert_eq!(decode(&d).err(), Some(Drop::Malformed), "magic");
    let mut d = good.clone();
    d[6] = 65;
    assert_eq!(decode(&d).err(), Some(Drop::Malformed), "header length");
    let mut d = good.clone();
    d[4] = 2;
    assert_eq!(decode(&d).err(), Some(Drop::Version));
    assert_eq!(decode(&good[..good.len() - 1]).err(), Some(Drop::Truncated));
    let mut d = good.clone();
    d.push(0);
    assert_eq!(decode(&d).err(), Some(Drop::Truncated), "a byte too many");
    let mut d = good.clone();
    d[48..52].copy_from_slice(&0u32.to_le_bytes());
    assert_eq!(decode(&d[..HEADER]).err(), Some(Drop::Truncated), "no bodies");
    let mut d = good.clone();
    d[48..52].copy_from_slice(&u32::MAX.to_le_bytes());
    assert_eq!(decode(&d).err(), Some(Drop::Truncated), "a huge count does not overflow");
    let mut d = good.clone();
    d[5] |= FLAG_AUTH;
    assert_eq!(decode(&d).err(), Some(Drop::Truncated), "AUTH without its tag");
    // Not finite, and not a rotation.
    let mut b = identity_at(1.0);
    b[1] = f64::NAN;
    let d = enc(MODEL, 3, [0; 8], 1, 0, 0.0, &[b], false, None);
    assert_eq!(poses_into(&decode(&d).expect("form"), &mut Vec::new()).err(), Some(Drop::Invalid));
    let mut b = identity_at(1.0);
    b[3] = 2.0;
    let d = enc(MODEL, 3, [0; 8], 1, 0, 0.0, &[b], false, None);
    assert_eq!(poses_into(&decode(&d).expect("form"), &mut Vec::new()).err(), Some(Drop::Invalid));
    let mirror = [0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
    let d = enc(MODEL, 3, [0; 8], 1, 0, 0.0, &[mirror], false, None);
    assert_eq!(poses_into(&decode(&d).expect("form"), &mut Vec::new()).err(), Some(Drop::Invalid), "a mirror is no pose");
}

#[test]
fn poses_are_frame_a_to_world() {
    // R.T maps world to frame_a: a body turned +90° about z has R.T = Rz(-90°).
    let b = [0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 1.0];
    let d = enc(MODEL, 1, [0; 8], 1, 0, 0.0, &[b], false, None);
    let mut p = Vec::new();
    poses_into(&decode(&d).expect("form"), &mut p).expect("poses");
    let h = std::f32::consts::FRAC_1_SQRT_2;
    for (got, want) in p[3..].iter().zip([0.0, 0.0, h, h]) {
        assert!((got - want).abs() < 1e-6, "{p:?}");
    }
}

#[test]
fn signatures_match_an_independent_hmac() {
    // Python: key = sha256(b"c2m_test"); hmac.new(key, b"hello", sha256), sha256(key)[:8].
    let key: [u8; 32] = Sha256::digest(b"c2m_test").into();
    let (id, k) = (key_id(&key), key);
    assert_eq!(hex::encode(id), "862c1e6f79235283");
    let f = Frame {
        flags: FLAG_AUTH,
        model: MODEL,
        version: 1,
        layout: [0; 8],
        seq: 0,
        time: 0.0,
        run: 0,
        key_id: id,
        bodies: &[],
        signed: b"hello",
        tag: Some(&hex::decode("ddc7be0b32fe324521a7181dc3ce609fdb1644ce6454f5a0844603d7565d89a9").expect("hex")),
    };
    assert!(verify(&f, &k));
    let other: [u8; 32] = Sha256::digest(b"c2m_other").into();
    assert!(!verify(&f, &other));

    let d = enc(MODEL, 3, [0; 8], 1, 0, 0.5, &[identity_at(1.0)], false, Some("c2m_test"));
    let f = decode(&d).expect("form");
    assert_eq!(f.key_id, id);
    assert!(verify(&f, &k));
    let mut bad = d.clone();
    bad[70] ^= 1;
    assert!(!verify(&decode(&bad).expect("form"), &k), "a changed body byte breaks the tag");
}

#[test]
fn runs_count_loss_order_and_rate() {
    let mut r = RunStats::new(5);
    assert_eq!(r.accept(0, 0.0, false, 100.0), Accept::Newer { lost: 0 });
    assert_eq!(r.accept(1, 0.02, false, 100.02), Accept::Newer { lost: 0 });
    assert_eq!(r.accept(4, 0.08, false, 100.08), Accept::Newer { lost: 2 });
    assert_eq!(r.accept(3, 0.06, false, 100.09), Accept::Stale, "late");
    assert_eq!(r.accept(4, 0.08, false, 100.09), Accept::Stale, "duplicate");
    for k in 5..=50 {
        r.accept(k, f64::from(k) * 0.02, k == 50, 100.0 + f64::from(k) * 0.04);
    }
    assert_eq!((r.frames, r.lost, r.stale, r.ended), (49, 2, 2, true));
    // 50 frames per simulated second, played at half speed: 25 Hz, factor 0.5.
    assert!((r.rate_hz - 25.0).abs() < 1.0, "{}", r.rate_hz);
    assert!((r.realtime_factor - 0.5).abs() < 0.02, "{}", r.realtime_factor);
    // Sequence numbers wrap.
    let mut w = RunStats::new(1);
    w.accept(u32::MAX, 0.0, false, 0.0);
    assert_eq!(w.accept(0, 0.02, false, 0.02), Accept::Newer { lost: 0 });
    assert_eq!(w.accept(u32::MAX, 0.0, false, 0.03), Accept::Stale);
}
