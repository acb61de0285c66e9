//! Output files written whole or not at all.
//!
//! A command stages each file it will write with [`OutputFiles::stage`], which hands back a
//! temporary path in the same directory as the file (same extension, so writers that pick the
//! format from it — plotters' bitmap backend — still do), writes everything there and calls
//! [`OutputFiles::commit`] once every file is complete: each temporary is then renamed over its
//! final name (`rename(2)`, atomic within one file system, hence the same directory). If the
//! command fails before the commit, dropping the set deletes the temporaries, so no new or
//! half-written file is left behind and files of an earlier run keep their content.
//!
//! The temporaries come from the `tempfile` crate (unique names created with `O_EXCL`,
//! deleted on drop, renamed by `TempPath::persist`) rather than hand-made names.

use std::io;
use std::path::{Path, PathBuf};

use tempfile::TempPath;

/// The files one command writes, staged under temporary names until [`Self::commit`].
#[derive(Debug, Default)]
pub struct OutputFiles {
    staged: Vec<(TempPath, PathBuf)>,
}

impl OutputFiles {
    /// An empty set.
    pub fn new() -> Self {
        Self::default()
    }

    /// Stages `path`: returns the temporary path to write its content to. The temporary is a
    /// hidden file next to `path` (`.<name>.<random>.<extension>`); it is created empty here,
    /// so an unwritable directory, or a directory named `path`, is reported now, naming
    /// `path`.
    pub fn stage(&mut self, path: &Path) -> io::Result<PathBuf> {
        let name = path.file_name().ok_or_else(|| {
            io::Error::new(
                io::ErrorKind::InvalidInput,
                format!("{} does not name a file", path.display()),
            )
        })?;
        // A directory in the way would only fail at the rename, after earlier files of the set
        // were renamed into place: refuse it now.
        if path.is_dir() {
            return Err(io::Error::new(
                io::ErrorKind::IsADirectory,
                format!("cannot write {}: it is a directory", path.display()),
            ));
        }
        let dir = match path.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        let mut prefix = std::ffi::OsString::from(".");
        prefix.push(name);
        prefix.push(".");
        let suffix = path
            .extension()
            .map(|e| {
                let mut s = std::ffi::OsString::from(".");
                s.push(e);
                s
            })
            .unwrap_or_default();
        let temp = tempfile::Builder::new()
            .prefix(&prefix)
            .suffix(&suffix)
            .tempfile_in(dir)
            .map_err(|e| {
                // tempfile appends `at path "<temporary>"`; the user named `path`, not that.
                let text = e.to_string();
                let reason = text.split(" at path ").next().unwrap_or(&text);
                io::Error::new(
                    e.kind(),
                    format!("cannot create {}: {reason}", path.display()),
                )
            })?
            .into_temp_path();
        let temp_path = temp.to_path_buf();
        self.staged.push((temp, path.to_path_buf()));
        Ok(temp_path)
    }

    /// Renames every staged file to its final name, in the order staged. A file whose rename
    /// fails is deleted, as are those after it; the error names it.
    pub fn commit(self) -> io::Result<()> {
        for (temp, path) in self.staged {
            temp.persist(&path).map_err(|e| {
                io::Error::new(
                    e.error.kind(),
                    format!("cannot write {}: {}", path.display(), e.error),
                )
            })?;
        }
        Ok(())
    }
}

/// Writes `path` whole or not at all with `write`, which is given the temporary path to write
/// (a one-file [`OutputFiles`]).
pub fn write_with<E: From<io::Error>>(
    path: &Path,
    write: impl FnOnce(&Path) -> Result<(), E>,
) -> Result<(), E> {
    let mut files = OutputFiles::new();
    let temp = files.stage(path)?;
    write(&temp)?;
    Ok(files.commit()?)
}

/// Writes `bytes` to `path` whole or not at all (a one-file [`OutputFiles`]).
pub fn write_file(path: &Path, bytes: impl AsRef<[u8]>) -> io::Result<()> {
    let mut files = OutputFiles::new();
    let temp = files.stage(path)?;
    std::fs::write(&temp, bytes)
        .map_err(|e| io::Error::new(e.kind(), format!("cannot write {}: {e}", path.display())))?;
    files.commit()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    #[test]
    fn a_set_dropped_before_commit_leaves_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let mut files = OutputFiles::new();
        let a = files.stage(&dir.path().join("a.csv")).unwrap();
        std::fs::write(&a, "x").unwrap();
        assert!(a.extension().is_some_and(|e| e == "csv"));
        assert_eq!(a.parent(), Some(dir.path()));
        drop(files);
        assert!(names(dir.path()).is_empty());
    }

    #[test]
    fn commit_renames_every_file_and_replaces_old_content() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("b.png"), "old").unwrap();
        let mut files = OutputFiles::new();
        for name in ["a.csv", "b.png"] {
            let temp = files.stage(&dir.path().join(name)).unwrap();
            std::fs::write(temp, name).unwrap();
        }
        assert_eq!(names(dir.path()).len(), 3, "two staged, one old");
        files.commit().unwrap();
        assert_eq!(names(dir.path()), ["a.csv", "b.png"]);
        let b = std::fs::read_to_string(dir.path().join("b.png")).unwrap();
        assert_eq!(b, "b.png");
    }

    #[test]
    fn a_directory_in_the_way_is_refused_at_stage() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::create_dir(dir.path().join("b.png")).unwrap();
        let mut files = OutputFiles::new();
        files.stage(&dir.path().join("a.csv")).unwrap();
        let err = files.stage(&dir.path().join("b.png")).unwrap_err();
        assert!(
            err.to_string().contains("b.png: it is a directory"),
            "{err}"
        );
        drop(files);
        assert_eq!(names(dir.path()), ["b.png"]);
    }

    #[test]
    fn an_unwritable_directory_is_refused_at_stage_naming_the_file() {
        let err = OutputFiles::new()
            .stage(Path::new("/proc/x.png"))
            .unwrap_err();
        assert!(err.to_string().contains("/proc/x.png"), "{err}");
    }
}
