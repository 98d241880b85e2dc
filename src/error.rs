//! Rust-level errors: what GL itself cannot report through `get_error` (bad framebuffer sizes,
//! I/O, a malformed recording, a backend that cannot start).

use std::fmt;

/// An error at the Rust level. GL errors proper (INVALID_ENUM, ...) are never an `Error`: they go to
/// the context's sticky error flag, read by `Context::get_error`, exactly as in GL.
#[derive(Debug)]
pub enum Error {
    /// `Context::new` was given a zero or oversized dimension.
    InvalidSize {
        /// The width asked for.
        width: u32,
        /// The height asked for.
        height: u32,
    },
    /// `Context::new` could not allocate the framebuffer (9 bytes a pixel): the size was valid
    /// but the memory is not there.
    OutOfMemory {
        /// The width asked for.
        width: u32,
        /// The height asked for.
        height: u32,
    },
    /// `Context::new` could not start the CPU backend's worker threads (rayon's pool): the
    /// process is out of threads or address space. The message is the system's.
    Threads(String),
    /// Reading or writing a file failed.
    Io(std::io::Error),
    /// A recording file could not be parsed; `line` and `column` are 1-based and refer to the
    /// text as the user wrote it.
    Parse {
        /// The 1-based line number.
        line: usize,
        /// The 1-based column (a byte offset: the parts of a line that are read are ASCII).
        column: usize,
        /// What is wrong with it: one short line.
        message: String,
    },
    /// Encoding or decoding an image failed.
    Image(String),
    /// The real-GL backend could not be set up; the message says what is missing and what to install.
    Backend(String),
    /// A window could not be opened or shown (`fixedgl::window`): no display to open it on, a
    /// window system that refused it, or a build without the `window` feature. The message says
    /// which, and what to do.
    Window(String),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::InvalidSize { width, height } => write!(
                f,
                "invalid framebuffer size {width}x{height}: each side must be 1..={}",
                crate::state::MAX_VIEWPORT_DIM
            ),
            Error::OutOfMemory { width, height } => write!(
                f,
                "out of memory for a {width}x{height} framebuffer (9 bytes a pixel)"
            ),
            Error::Threads(m) => write!(f, "cannot start the CPU backend's threads: {m}"),
            Error::Io(e) => write!(f, "I/O error: {e}"),
            Error::Parse {
                line,
                column,
                message,
            } => write!(f, "line {line}, column {column}: {message}"),
            Error::Image(m) => write!(f, "image error: {m}"),
            Error::Backend(m) => write!(f, "GL backend: {m}"),
            Error::Window(m) => write!(f, "window: {m}"),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Io(e) => Some(e),
            _ => None,
        }
    }
}

impl From<std::io::Error> for Error {
    fn from(e: std::io::Error) -> Self {
        Error::Io(e)
    }
}

impl From<image::ImageError> for Error {
    fn from(e: image::ImageError) -> Self {
        Error::Image(e.to_string())
    }
}
