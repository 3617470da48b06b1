//! Fixtures shared by the unit tests of the UI.

use crate::model::scene::Scene;

/// The paper's Fig. 5 scene: a steel sphere R = 10 mm on a steel plate, v₀ = 0.3 m/s, e = 0.6,
/// x_pl = 2.3 µm.
pub fn fig5_scene() -> Scene {
    Scene {
        name: "fig5".into(),
        ..crate::model::scene::tests::fig5_scene()
    }
}

pub(crate) use crate::model::scene::tests::fig5_params;

/// The path `name` in a fresh temporary folder of its own (`name` itself is not created). The
/// folder goes, with whatever the test wrote there, when this drops: also when the test fails.
pub struct TempPath {
    path: std::path::PathBuf,
    _folder: tempfile::TempDir,
}

/// `name` in a fresh folder `hertz-tui-ui-…` under the system temp dir.
pub fn temp_path(name: &str) -> TempPath {
    let folder = tempfile::Builder::new()
        .prefix("hertz-tui-ui-")
        .tempdir()
        .expect("a folder in the temp dir");
    TempPath {
        path: folder.path().join(name),
        _folder: folder,
    }
}

impl std::ops::Deref for TempPath {
    type Target = std::path::Path;

    fn deref(&self) -> &std::path::Path {
        &self.path
    }
}

impl AsRef<std::path::Path> for TempPath {
    fn as_ref(&self) -> &std::path::Path {
        &self.path
    }
}
