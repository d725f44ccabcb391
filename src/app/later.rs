//! A stage of a scene's solve that lands after its run (the run without contact, the error
//! estimate): what is shown until it does.

/// A stage that comes after the run: on its way, landed, or not coming (its request ended
/// without it; the error line says why).
pub(crate) enum Later<T> {
    Pending,
    Ready(T),
    Missing,
}

impl<T> Later<T> {
    pub(crate) fn ready(&self) -> Option<&T> {
        match self {
            Later::Ready(t) => Some(t),
            _ => None,
        }
    }

    /// What a readout shows in place of the stage's value.
    pub(crate) fn absent(&self) -> &'static str {
        match self {
            Later::Missing => "not solved",
            _ => "pending",
        }
    }
}
