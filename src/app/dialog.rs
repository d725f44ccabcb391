//! Native file dialogs (rfd, through the XDG desktop portal on Linux). A dialog runs on a thread
//! of its own, so the window keeps drawing while it is open; the choice comes back by `poll`.
//! Where no portal answers, the dialog returns nothing and the typed path fields still work.

use std::path::PathBuf;
use std::sync::mpsc::{Receiver, Sender, channel};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Purpose {
    OpenScene,
    SaveScene,
    ExportFolder,
    Motion,
}

pub struct Dialogs {
    tx: Sender<(Purpose, Option<PathBuf>)>,
    rx: Receiver<(Purpose, Option<PathBuf>)>,
    open: bool,
}

impl Default for Dialogs {
    fn default() -> Self {
        let (tx, rx) = channel();
        Dialogs {
            tx,
            rx,
            open: false,
        }
    }
}

impl Dialogs {
    /// Opens a dialog unless one is already open.
    pub fn ask(&mut self, purpose: Purpose, start: &str) {
        if self.open {
            return;
        }
        self.open = true;
        let tx = self.tx.clone();
        let start = PathBuf::from(start.trim());
        std::thread::spawn(move || {
            let mut d = rfd::FileDialog::new();
            if let Some(dir) = start.parent().filter(|d| d.is_dir()) {
                d = d.set_directory(dir);
            }
            let chosen = match purpose {
                Purpose::OpenScene => d.add_filter("scene (TOML)", &["toml"]).pick_file(),
                Purpose::SaveScene => d
                    .add_filter("scene (TOML)", &["toml"])
                    .set_file_name("scene.toml")
                    .save_file(),
                Purpose::ExportFolder => d.pick_folder(),
                Purpose::Motion => d
                    .add_filter("ground motion", &["AT2", "at2", "txt", "csv", "dat"])
                    .pick_file(),
            };
            let _ = tx.send((purpose, chosen));
        });
    }

    pub fn is_open(&self) -> bool {
        self.open
    }

    /// A closed dialog's purpose and choice (`None`: cancelled, or no dialog could open).
    pub fn poll(&mut self) -> Option<(Purpose, Option<PathBuf>)> {
        let r = self.rx.try_recv().ok();
        if r.is_some() {
            self.open = false;
        }
        r
    }
}

/// What to say when a dialog gave nothing back.
pub const NOTHING_CHOSEN: &str =
    "no file chosen (if no dialog appeared, this desktop has no file-dialog portal: type the path)";
