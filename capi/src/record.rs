//! What `fixedgl run --record FILE` and `--compare DIR` ask of the library, through the
//! environment of the program they start:
//! - `FIXEDGL_RECORD=FILE`: each context records its calls; at each present the calls since the
//!   last one are appended to its file (the first context made gets FILE, the next FILE.2, ...)
//!   in the recording format, followed by a marker comment `# frame N WxH`;
//! - `FIXEDGL_FRAMES_DIR=DIR`: each presented frame is also written as `DIR/ctxK-frameNNNN.png`,
//!   the picture the program showed, for the comparison with the driver's replay.
//!
//! Failing to write is said once on stderr and stops the recording; the program goes on.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};

use fixedgl::Context;

/// Contexts made so far (numbers them for file names).
static CONTEXTS: AtomicUsize = AtomicUsize::new(0);

/// One context's recording and frame output.
pub(crate) struct Recorder {
    number: usize,
    frame: usize,
    calls: Option<BufWriter<File>>,
    frames: Option<PathBuf>,
}

impl Recorder {
    /// The recorder the environment asks for, if any; starts `ctx`'s recording.
    pub(crate) fn from_env(ctx: &mut Context) -> Option<Recorder> {
        let record = std::env::var_os("FIXEDGL_RECORD");
        let frames = std::env::var_os("FIXEDGL_FRAMES_DIR").map(PathBuf::from);
        if record.is_none() && frames.is_none() {
            return None;
        }
        let number = CONTEXTS.fetch_add(1, Ordering::Relaxed) + 1;
        let calls = record.and_then(|path| {
            let mut path = PathBuf::from(path);
            if number > 1 {
                let mut name = path.file_name().unwrap_or_default().to_os_string();
                name.push(format!(".{number}"));
                path.set_file_name(name);
            }
            match File::create(&path) {
                Ok(f) => Some(BufWriter::new(f)),
                Err(e) => {
                    eprintln!("fixedgl: cannot record to {}: {e}", path.display());
                    None
                }
            }
        });
        if let Some(dir) = &frames {
            if let Err(e) = std::fs::create_dir_all(dir) {
                eprintln!("fixedgl: cannot write frames to {}: {e}", dir.display());
            }
        }
        if calls.is_some() {
            ctx.start_recording();
        }
        Some(Recorder {
            number,
            frame: 0,
            calls,
            frames,
        })
    }

    /// A frame was presented: the calls since the last one and the marker; the picture.
    pub(crate) fn presented(&mut self, ctx: &mut Context) {
        self.frame += 1;
        let (w, h) = ctx.size();
        if let Some(out) = self.calls.as_mut() {
            let calls = ctx.stop_recording();
            let written = fixedgl::recording::write_recording(&calls, &mut *out)
                .map_err(|e| e.to_string())
                .and_then(|()| {
                    writeln!(out, "# frame {} {w}x{h}", self.frame).map_err(|e| e.to_string())
                })
                .and_then(|()| out.flush().map_err(|e| e.to_string()));
            match written {
                Ok(()) => ctx.start_recording(),
                Err(e) => {
                    eprintln!("fixedgl: recording stopped: {e}");
                    self.calls = None;
                }
            }
        }
        if let Some(dir) = &self.frames {
            let path = dir.join(format!("ctx{}-frame{:04}.png", self.number, self.frame));
            if let Err(e) = ctx.to_image().save(&path) {
                eprintln!("fixedgl: cannot write {}: {e}; frames stop", path.display());
                self.frames = None;
            }
        }
    }
}
