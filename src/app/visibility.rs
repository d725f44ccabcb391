//! What a scene shows, and which of its settings may be changed: everything, unless a lesson
//! step names the panels it needs and the settings it unlocks ("leave out what a step does not
//! need"). The names are the lesson format's (`docs/lessons.md`).

use std::collections::BTreeSet;

/// The panels a scene draws.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Visibility {
    /// `None`: every panel.
    only: Option<BTreeSet<String>>,
}

impl Visibility {
    /// Only these panels (none at all: the result views wait for a prediction).
    pub fn only<S: AsRef<str>>(names: impl IntoIterator<Item = S>) -> Self {
        Visibility {
            only: Some(names.into_iter().map(|s| s.as_ref().to_string()).collect()),
        }
    }

    /// Whether `panel` (a lesson panel name: bars, buildings, force, approach, displacements,
    /// readouts, xt, energy, impacts, gaps, hysteresis) is drawn.
    pub fn shows(&self, panel: &str) -> bool {
        self.only.as_ref().is_none_or(|s| s.contains(panel))
    }
}

/// Which settings a lesson step leaves open; the others are locked in place.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Lock {
    unlocked: BTreeSet<String>,
    /// Locked rows are left out altogether (lecture mode), not shown greyed.
    pub hide_locked: bool,
}

impl Lock {
    pub fn unlocking<S: AsRef<str>>(keys: impl IntoIterator<Item = S>, hide_locked: bool) -> Self {
        Lock {
            unlocked: keys.into_iter().map(|s| s.as_ref().to_string()).collect(),
            hide_locked,
        }
    }

    /// Whether the row of `id` may change: its key is unlocked, or the list it is one entry of
    /// (`left.masses.2` belongs to `left.masses`; a per-storey list and its one-value key,
    /// `left.mass`, unlock each other).
    pub fn opens(&self, id: &str) -> bool {
        if self.unlocked.contains(id) {
            return true;
        }
        let base = match id.rsplit_once('.') {
            Some((head, tail)) if tail.chars().all(|c| c.is_ascii_digit()) => head,
            _ => id,
        };
        let singular = base.strip_suffix("es").or_else(|| base.strip_suffix('s'));
        self.unlocked.contains(base)
            || singular.is_some_and(|s| self.unlocked.contains(s))
            || self.unlocked.contains(&format!("{base}s"))
            || self.unlocked.contains(&format!("{base}es"))
    }

    /// Whether nothing in the group of keys starting with `prefix` is open.
    pub fn closes_all(&self, prefix: &str) -> bool {
        !self.unlocked.iter().any(|k| k.starts_with(prefix))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_step_shows_only_its_panels_and_opens_only_its_keys() {
        let v = Visibility::only(["force", "xt"]);
        assert!(v.shows("xt") && !v.shows("energy"));
        assert!(Visibility::default().shows("energy"));
        assert!(!Visibility::only(Vec::<String>::new()).shows("force"));
        let l = Lock::unlocking(["bar2.length", "left.masses", "right.stiffness"], false);
        assert!(l.opens("bar2.length") && !l.opens("bar1.length"));
        assert!(l.opens("left.masses.2") && l.opens("left.mass"));
        assert!(l.opens("right.stiffnesses") && l.opens("right.stiffnesses.0"));
        assert!(!l.opens("right.masses.0"));
        assert!(l.closes_all("contact.") && !l.closes_all("bar2."));
    }
}
