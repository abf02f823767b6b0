//! Collision geometry and interference checks, no IO: convex shapes per body from its CAD mesh
//! (primitive, hull or convex decomposition), distances and penetrations of body pairs at a pose
//! and along a motion. Used by the pipeline (shapes, CAD-pose interferences in the report), the
//! Modelica back end (the shapes the C collision code receives) and the service (motions).

/// One convex piece of a body's collision shape, in the body's frame_a (CS1) coordinates,
/// metres: the convex hull of `vertices`, grown by `radius` (a sphere is one vertex with a
/// radius, a capsule two; polytopes have radius 0). `faces` (triangles of the hull, outward)
/// are for files and drawing; distances need only the vertices.
#[derive(Clone, Debug, PartialEq)]
pub struct ConvexPart {
    pub vertices: Vec<[f64; 3]>,
    pub faces: Vec<[u32; 3]>,
    pub radius: f64,
}

mod cache;
mod check;
mod shape;
#[cfg(test)]
mod tests;

pub use cache::{shape_bytes, CacheStats, MemoryShapeCache, ShapeCache, ShapeKey, DEFAULT_CACHE_BYTES};
pub use check::{contacts_at, contacts_of, sweep, Contact, PairSweep, Sweep, SweepOptions, World};
pub(crate) use shape::hull_part;
pub use shape::{body_shape, decomposition_plan, obj_text, BodyShape, DecompositionPlan, ShapeKind, ShapeOptions};
