//! The physics core: no GUI, GPU, file formats or printing.

#![warn(missing_docs)]

/// The names of an enum's variants in the order of its `ALL`, as a const array: each enum's
/// `name()` is the one place a name is written, and the settings table's choices are this array.
macro_rules! names_of {
    ($all:expr, $n:literal) => {{
        let mut names = [""; $n];
        let mut i = 0;
        while i < $n {
            names[i] = $all[i].name();
            i += 1;
        }
        names
    }};
}
pub(crate) use names_of;

pub mod bar;
pub(crate) mod bound;
pub mod bridge;
pub mod building;
pub mod contact;
pub mod control;
pub mod error;
pub mod field;
pub mod history;
pub mod hysteresis;
pub mod impact;
pub mod material;
pub mod motion;
pub(crate) mod ring;
pub(crate) mod ringing;
pub mod root;
pub mod scenario;
pub mod settings;
pub mod xt;
