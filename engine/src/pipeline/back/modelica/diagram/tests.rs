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

/// Whether a route is orthogonal and stays out of every component's extent (the layout check's
/// rules, on the sheet).
fn clean(s: &Sheet, w: &Wire) -> Result<(), String> {
    if w.points.len() < 2 {
        return Err(format!("{} - {}: no route", w.a, w.b));
    }
    for p in w.points.windows(2) {
        let ((x1, y1), (x2, y2)) = (p[0], p[1]);
        if x1 != x2 && y1 != y2 {
            return Err(format!("not orthogonal: {p:?}"));
        }
        let (lx, hx, ly, hy) = (x1.min(x2), x1.max(x2), y1.min(y2), y1.max(y2));
        for (name, c) in &s.placed {
            let r = c.rect();
            if lx < f64::from(r.x2) && hx > f64::from(r.x1) && ly < f64::from(r.y2) && hy > f64::from(r.y1) {
                return Err(format!("{} - {}: {p:?} passes through {name}", w.a, w.b));
            }
        }
    }
    Ok(())
}

#[test]
fn a_wire_too_long_to_search_falls_back_to_a_clear_route_with_bounded_work() {
    // A column of 400 components with a free corridor beside it, and a wire from its top to
    // its foot: 8,000 grid steps, more than a wire may search.
    let mut s = Sheet::default();
    for k in 0..400 {
        s.add(&format!("c{k}"), Class::TwoPort, Want { x: 0, y: -100 * k, half: 20, flip: false });
    }
    s.add("a", Class::TwoPort, want(-200, 0));
    s.add("b", Class::TwoPort, want(200, -40_000));
    let before = s.work();
    s.connect("a.frame_b", "b.frame_a", Style::Frame);
    let work = s.work() - before;
    let w = &s.wires[0];
    assert_eq!(w.points.first(), Some(&(-190.0, 0.0)));
    assert_eq!(w.points.last(), Some(&(190.0, -40_000.0)));
    clean(&s, w).unwrap_or_else(|e| panic!("{e}: {:?}", w.points));
    assert!(work < 1_000, "{work} units of work for one wire");
}

#[test]
fn the_fallback_threads_channels_between_rows_and_columns() {
    // A grid of components (rows 100 apart, columns 120 apart) and wires between far cells:
    // every one routed cleanly, by search or by the fallback.
    let mut s = Sheet::default();
    for i in 0..30 {
        for j in 0..40 {
            s.add(&format!("c{i}_{j}"), Class::TwoPort, Want { x: 120 * i, y: -100 * j, half: 20, flip: false });
        }
    }
    for k in 0..20 {
        let (a, b) = (format!("c{}_{}", k % 3, (k * 7) % 40), format!("c{}_{}", 29 - k % 5, 39 - (k * 3) % 40));
        s.connect(&format!("{a}.frame_b"), &format!("{b}.frame_a"), Style::Frame);
    }
    for w in &s.wires {
        clean(&s, w).unwrap_or_else(|e| panic!("{e}: {:?}", w.points));
    }
    assert!(s.work() <= 20 * (WIRE_EXPANSIONS + 5_000), "work {}", s.work());
}

#[test]
fn open_intervals_merge_and_answer_segment_queries() {
    let mut m = Intervals::new();
    add_interval(&mut m, 0, 10);
    add_interval(&mut m, 20, 30);
    add_interval(&mut m, 5, 22);
    assert_eq!(m, vec![(0, 30)]);
    // Kept in order; touching intervals stay apart, an inner one is absorbed.
    let mut m = Intervals::new();
    for (a, b) in [(50, 60), (0, 10), (30, 40), (10, 20), (32, 35), (-20, -10), (55, 70)] {
        add_interval(&mut m, a, b);
    }
    assert_eq!(m, vec![(-20, -10), (0, 10), (10, 20), (30, 40), (50, 70)]);
    assert!(meets(Some(&m), 45, 52));
    assert!(!meets(Some(&m), 41, 49));
    assert!(!meets(Some(&m), 40, 50), "between (30, 40) and (50, 70), touching both");
    assert!(meets(Some(&m), 5, 5));
    let mut m = Intervals::new();
    add_interval(&mut m, 0, 10);
    add_interval(&mut m, 10, 20);
    assert!(!meets(Some(&m), 10, 10), "a point between two boxes");
    assert!(meets(Some(&m), 9, 9));
    assert!(!meets(Some(&m), -5, 0), "touching the edge");
    assert!(meets(Some(&m), 25, -5));
    assert!(!meets(Some(&m), 20, 40));
    assert!(!meets(None, 0, 5));
}

/// The Mechatronics text of the contact-force writer (an `inner` collision world, a
/// `BodyForce` per body on the body's frame_a, no signal wires) around a base of three bodies.
#[test]
fn contact_forces_stand_beside_their_bodies_with_short_wires() {
    let mut base = Sheet::default();
    base.add("world", Class::World, want(0, 0));
    for (k, b) in ["B1", "B2", "B3"].iter().enumerate() {
        let k = k as i32;
        base.add(b, Class::TwoPort, Want { x: 200 + 160 * k, y: -100 * k, half: 20, flip: false });
        base.add(&format!("{b}_shape"), Class::TwoPort, Want { x: 200 + 160 * k, y: -100 * k - 100, half: 20, flip: false });
    }
    let ph = extend::PLACEHOLDER;
    let mut text = format!(
        "within P;\nmodel Mechatronics \"M\"\n  extends P.Mechanics;\n  parameter Boolean collisions = false \"Contacts\";\n  inner P.Components.Collision.World collisionWorld(nBodies=3, nParts=3) if collisions \"Contact forces between the collision shapes\"\n    {ph};\n"
    );
    for (k, b) in ["B1", "B2", "B3"].iter().enumerate() {
        text.push_str(&format!(
            "  P.Components.Collision.BodyForce collisionForce_{b}(index={}) if collisions \"Contact force and torque on {b} (from collisionWorld)\"\n    {ph};\n",
            k + 1
        ));
    }
    text.push_str("equation\n");
    for b in ["B1", "B2", "B3"] {
        text.push_str(&format!("  connect(collisionForce_{b}.frame_b, {b}.frame_a);\n"));
    }
    text.push_str("end Mechatronics;\n");
    let (out, _, work) = extend::lay_out_counted(&text, base.clone());
    assert!(!out.contains(ph), "{out}");
    let drawing = svg::read(&out);
    let at = |name: &str| {
        drawing
            .components
            .iter()
            .find(|c| c.name == name)
            .map(|c| ((c.extent[0].0 + c.extent[1].0) / 2.0, (c.extent[0].1 + c.extent[1].1) / 2.0))
    };
    // The collision world: in the column left of everything.
    let (wx, _) = at("collisionWorld").unwrap_or_else(|| panic!("collisionWorld placed: {out}"));
    assert!(wx < -20.0, "{out}");
    for b in ["B1", "B2", "B3"] {
        let body = base.placed[b];
        let (fx, fy) = at(&format!("collisionForce_{b}")).unwrap_or_else(|| panic!("force of {b}: {out}"));
        assert!(
            (fx - f64::from(body.x)).abs() <= 60.0 && (fy - f64::from(body.y)).abs() <= 60.0,
            "{b}: force at {fx},{fy}, body at {},{}",
            body.x,
            body.y
        );
        let line =
            drawing.lines.iter().find(|l| l.a == format!("collisionForce_{b}.frame_b")).unwrap_or_else(|| panic!("wire of {b}: {out}"));
        assert!(line.points.len() <= 4, "{b}: {:?}", line.points);
        let length: f64 = line.points.windows(2).map(|p| (p[0].0 - p[1].0).abs() + (p[0].1 - p[1].1).abs()).sum();
        assert!(length <= 80.0, "{b}: {length} long: {:?}", line.points);
    }
    assert!(work < 1_000, "{work}");
}

#[test]
fn declarations_may_start_with_inner() {
    let text =
        format!("  inner P.Components.Collision.World collisionWorld(nBodies=3) if collisions \"World\"\n    {};\n", extend::PLACEHOLDER);
    let (out, _) = extend::lay_out(&text, Sheet::default());
    assert!(!out.contains(extend::PLACEHOLDER), "{out}");
    assert_eq!(svg::read(&out).components.first().map(|c| c.name.as_str()), Some("collisionWorld"), "{out}");
}

#[test]
fn hundreds_of_components_wanting_one_spot_are_placed_with_bounded_work() {
    // 1,000 components that all want the same spot: each tries at most `SPOTS_PER_ADD` spots (and
    // one ring more) before it stands under everything, so the work is linear in the count.
    let mut s = Sheet::default();
    let n = 1_000u64;
    for k in 0..n {
        s.add(&format!("c{k}"), Class::TwoPort, want(0, 0));
    }
    assert!(s.work() <= n * (SPOTS_PER_ADD + 8 * 30), "work {}", s.work());
    let rects: Vec<Rect> = s.placed.values().map(Placed::rect).collect();
    for (i, a) in rects.iter().enumerate() {
        assert!(rects[i + 1..].iter().all(|b| !a.overlaps(b)), "{a:?} overlaps");
    }
}

#[test]
fn wires_fanning_out_of_one_connector_share_a_short_trunk_and_need_no_search() {
    // A body's frame_a wired to three frames stacked below and to the right of it (a body's
    // coordinate systems): every wire leaves the connector along the same cells, and the later
    // ones are drawn without a search, each clean and with two bends.
    let mut s = Sheet::default();
    s.add("body", Class::TwoPort, want(10, 0));
    for k in 1..=3 {
        s.add(&format!("cs{k}"), Class::TwoPort, want(15, -100 - 100 * k));
    }
    for k in 1..=3 {
        s.connect("body.frame_a", &format!("cs{k}.frame_a"), Style::Frame);
    }
    for w in &s.wires {
        clean(&s, w).unwrap_or_else(|e| panic!("{e}: {:?}", w.points));
        assert_eq!(w.points.len(), 4, "{:?}", w.points);
    }
    assert_eq!(s.spent, 0, "A* expansions");
    // The later wires run on the first one's cells only next to the connector.
    let first: std::collections::HashSet<(i64, i64)> = s.wires[0].points.windows(2).flat_map(|p| cells(p[0], p[1])).collect();
    for w in &s.wires[1..] {
        let shared = w.points.windows(2).flat_map(|p| cells(p[0], p[1])).filter(|c| first.contains(c)).count();
        assert!((1..=route_trunk() + 2).contains(&shared), "{shared} cells shared: {:?}", w.points);
    }
}

/// The grid cells (units of 5) of a straight segment, both ends.
fn cells(a: (f64, f64), b: (f64, f64)) -> Vec<(i64, i64)> {
    let g = |v: f64| (v / 5.0).round() as i64;
    let (a, b) = ((g(a.0), g(a.1)), (g(b.0), g(b.1)));
    let n = (b.0 - a.0).abs() + (b.1 - a.1).abs();
    (0..=n).map(|k| (a.0 + k * (b.0 - a.0).signum(), a.1 + k * (b.1 - a.1).signum())).collect()
}

fn route_trunk() -> usize {
    route::TRUNK as usize
}

#[test]
fn a_long_wire_with_a_clear_elbow_is_drawn_without_a_search() {
    // Ends 1,000 grid units apart (longer than a search window's margin, shorter than a search
    // may go) and nothing between them: one elbow, found without expanding a node.
    let mut s = Sheet::default();
    s.add("a", Class::TwoPort, want(0, 0));
    s.add("b", Class::TwoPort, Want { x: 200, y: -4_800, half: 10, flip: false });
    let before = s.work();
    s.connect("a.frame_b", "b.frame_a", Style::Frame);
    let w = &s.wires[0];
    clean(&s, w).unwrap_or_else(|e| panic!("{e}: {:?}", w.points));
    assert_eq!(s.spent, 0, "A* expansions: {:?}", w.points);
    assert!(s.work() - before < 200, "{} units of work", s.work() - before);
}
