//! Scratch files and folders for the integration tests, each in a fresh folder under the system
//! temp dir that is removed with all it holds when its guard drops: at the end of the test, and
//! also when the test fails (the guard drops while the panic unwinds). The folders are named
//! `hertz-tui-<label>-…`, so anything a killed run leaves behind says which test made it.

use std::ops::Deref;
use std::path::{Path, PathBuf};

use tempfile::TempDir;

/// A fresh empty folder, removed with its content when dropped. Derefs to its path.
pub struct Folder(TempDir);

/// A fresh empty folder `hertz-tui-<label>-…`.
pub fn folder(label: &str) -> Folder {
    let dir = tempfile::Builder::new()
        .prefix(&format!("hertz-tui-{label}-"))
        .tempdir()
        .expect("a folder in the temp dir");
    Folder(dir)
}

impl Deref for Folder {
    type Target = Path;

    fn deref(&self) -> &Path {
        self.0.path()
    }
}

impl AsRef<Path> for Folder {
    fn as_ref(&self) -> &Path {
        self.0.path()
    }
}

/// The path `name` in a fresh folder of its own (`name` itself is not created): what the test
/// writes there goes when this is dropped. Derefs to the path.
pub struct ScratchPath {
    path: PathBuf,
    _folder: Folder,
}

/// `name` in a fresh folder `hertz-tui-<label>-…`.
pub fn path(label: &str, name: &str) -> ScratchPath {
    let folder = folder(label);
    ScratchPath {
        path: folder.join(name),
        _folder: folder,
    }
}

impl Deref for ScratchPath {
    type Target = Path;

    fn deref(&self) -> &Path {
        &self.path
    }
}

impl AsRef<Path> for ScratchPath {
    fn as_ref(&self) -> &Path {
        &self.path
    }
}
