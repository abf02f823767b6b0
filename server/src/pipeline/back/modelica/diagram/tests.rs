use super::*;

fn want(x: i32, y: i32) -> Want {
    Want { x, y, half: 10, flip: false }
}

#[test]
fn overlapping_wants_move_to_the_nearest_free_spot() {
    let mut s = Sheet::default();
    let a = s.add("a", Class::TwoPort, want(0, 0));
    let b = s.add("b", Class::TwoPort, want(0, 0));
    assert_eq!((a.x, a.y), (0, 0));
    assert!(!Sheet::keep_out(&a.rect()).overlaps(&Sheet::keep_out(&b.rect())), "{b:?}");
    // The nearest free spot: 30 units to the left (the name above needs more room than the
    // sides, so down is farther).
    assert_eq!((b.x, b.y), (-30, 0));
}

#[test]
fn wires_go_around_components_orthogonally() {
    let mut s = Sheet::default();
    s.add("a", Class::TwoPort, want(0, 0));
    s.add("wall", Class::TwoPort, Want { x: 60, y: 0, half: 20, flip: false });
    s.add("b", Class::TwoPort, want(120, 0));
    s.connect("a.frame_b", "b.frame_a", Style::Frame);
    let w = &s.wires[0];
    assert_eq!(w.points.first(), Some(&(10.0, 0.0)));
    assert_eq!(w.points.last(), Some(&(110.0, 0.0)));
    let wall = s.placed["wall"].rect();
    for p in w.points.windows(2) {
        let ((x1, y1), (x2, y2)) = (p[0], p[1]);
        assert!(x1 == x2 || y1 == y2, "not orthogonal: {p:?}");
        // Sample the segment: no point inside the wall.
        for k in 0..=20 {
            let t = f64::from(k) / 20.0;
            let (x, y) = (x1 + t * (x2 - x1), y1 + t * (y2 - y1));
            let inside = f64::from(wall.x1) < x && x < f64::from(wall.x2) && f64::from(wall.y1) < y && y < f64::from(wall.y2);
            assert!(!inside, "through the wall at {x},{y}: {:?}", w.points);
        }
    }
}

#[test]
fn mirrored_components_have_frame_a_on_the_right() {
    let p = Placed { x: 100, y: 50, half: 10, flip: true, class: Class::TwoPort };
    assert_eq!(p.port("frame_a"), Some(((110.0, 50.0), (1, 0))));
    assert_eq!(p.annotation(), "annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={100,50})))");
    let j = Placed { x: 0, y: 0, half: 10, flip: false, class: Class::Joint };
    assert_eq!(j.port("drive"), Some(((-6.0, 10.0), (0, 1))));
}

#[test]
fn hundreds_of_wires_through_one_corridor() {
    // A collision world wired to 300 bodies: every wire leaves by the same cells (more than a
    // cell's use count of 255 once overflowed).
    let mut s = Sheet::default();
    s.add("hub", Class::CollisionWorld, want(0, 0));
    for k in 0..300 {
        s.add(&format!("f{k}"), Class::TwoPort, want(100 + 40 * (k % 15), -40 * (k / 15)));
        s.connect("hub.force[1, :]", &format!("f{k}.frame_a"), Style::Signal);
    }
    assert_eq!(s.wires.len(), 300);
    assert!(s.wires.iter().all(|w| w.points.len() >= 2));
}
