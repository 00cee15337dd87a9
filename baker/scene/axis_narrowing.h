// Narrowing a catalogue axis to the values a scene uses, at the catalogue's precision.
#pragma once
#include "baker/tables/spec.h"

namespace kiln {

/// The axis over [lo, hi] (lo < hi) with the fewest nodes (at least 2) such that no cell is wider
/// than the catalogue axis `full`'s cell at the same place (beyond `full`'s ends: its end cells).
/// The warp is `full`'s, or linear when that needs fewer nodes. So the narrowed table keeps the
/// catalogue's node density (hence about its lookup error) and a narrower range has fewer nodes.
/// [lo, hi] equal to `full`'s range gives `full` itself.
AxisSpec NarrowAxis(const AxisSpec& full, double lo, double hi);

/// A 2-node linear slice with its first node exactly at v (its last when v is at or beyond
/// `full`'s upper end); the other node is the neighbouring node of `full`. A lookup at v returns
/// the value baked at v. For tables whose quantity reads every axis (dfg, albedo, albedo-avg).
AxisSpec SliceAxis(const AxisSpec& full, double v);

}  // namespace kiln
