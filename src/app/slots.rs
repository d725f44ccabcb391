//! The GPU slot of each wave-field view (`render::bars::FieldResources`): views drawn in the same
//! frame must not share one, or the last upload would win for all of them.

/// The Bar impact scene's bars.
pub const BAR_VIEW: u64 = 1;
/// The Wave vs lumped scene's bars.
pub const COMPARE_VIEW: u64 = 2;
/// The building scene's slabs.
pub const BUILDING_VIEW: u64 = 3;
/// The Bar impact scene's x-t diagram.
pub const BAR_XT: u64 = 10;
/// The Wave vs lumped scene's x-t diagrams, one per model shown.
pub const COMPARE_XT: u64 = 20;
/// The building scene's x-t diagram of the slabs.
pub const BUILDING_XT: u64 = 30;
/// The Bridge pounding scene's girders.
pub const BRIDGE_VIEW: u64 = 4;
/// The Bridge pounding scene's x-t diagram of the deck.
pub const BRIDGE_XT: u64 = 40;
