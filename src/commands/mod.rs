//! The command table: one row per GL command, the single list everything else is made from.
//!
//! A row joins what the Khronos registry (gl.xml) says of a command — its C prototype, parameter
//! names, the length of each pointer (a number, another argument, or a count function of a pname)
//! and its version — with what fixedgl says of it (`annotations.txt`): the `Context` method that
//! implements it, whether GL 2.1 §2.6.3 allows it between Begin and End, whether a display list
//! executes it immediately (§5.4), which count function sizes its pname-dependent vector.
//!
//! From the table `gen.rs` writes, and a test keeps fresh:
//! - `call/generated.rs`: the [`Call`](crate::Call) enum, its names, the Begin/End and display-list
//!   classifiers, and the recording format's argument kinds;
//! - `context/dispatch.rs`: the front end's `execute` for every call;
//! - `glbackend/generated.rs`: the GL replay, through safe wrappers of the driver's entry points;
//! - `table.rs`: [`COMMANDS`], every GL 1.0 to 1.5 command with its C signature (what a C ABI
//!   exports), implemented or not.
//!
//! Adding a command is one annotation line, its `Context` method and its CPU stage; the compiler
//! then points at anything else (a replay helper the line names, a count function).

mod table;

#[cfg(test)]
mod gen;

pub use table::COMMANDS;

/// One GL command of the table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Command {
    /// The C name (`glLightfv`).
    pub name: &'static str,
    /// The GL version that made it core (`1.0` to `2.1`).
    pub version: &'static str,
    /// The C return type (`void`, `GLuint`, ...).
    pub ret: &'static str,
    /// The parameters in order.
    pub params: &'static [Param],
    /// The [`Context`](crate::Context) method implementing it; `None` where fixedgl does not.
    pub method: Option<&'static str>,
    /// The [`counts`](crate::counts) function giving the length of its pname-dependent vector.
    pub count: Option<&'static str>,
    /// Whether GL 2.1 §2.6.3 allows it between Begin and End.
    pub inside: bool,
    /// Whether a display list executes it immediately instead of compiling it (GL 2.1 §5.4).
    pub immediate: bool,
}

/// One parameter of a [`Command`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Param {
    /// The C type as declared (`const GLfloat *`).
    pub c_type: &'static str,
    /// The parameter's name in the registry.
    pub name: &'static str,
    /// The registry's length of a pointer: a number, another parameter's name, or
    /// `COMPSIZE(...)` of the parameters it is computed from.
    pub len: Option<&'static str>,
    /// The registry's enum group (`LightParameter`, `PrimitiveType`, ...).
    pub group: Option<&'static str>,
}

impl Command {
    /// The row of the command named `name` (`glLightfv`), if the table has one.
    pub fn find(name: &str) -> Option<&'static Command> {
        COMMANDS.iter().find(|c| c.name == name)
    }

    /// The C prototype, as a header declares it (`void glLightfv(GLenum light, ...)`).
    pub fn c_prototype(&self) -> String {
        let params: Vec<String> = self
            .params
            .iter()
            .map(|p| {
                if p.c_type.ends_with('*') {
                    format!("{}{}", p.c_type, p.name)
                } else {
                    format!("{} {}", p.c_type, p.name)
                }
            })
            .collect();
        let params = if params.is_empty() {
            "void".to_string()
        } else {
            params.join(", ")
        };
        format!("{} {}({params})", self.ret, self.name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_lists_every_gl_1_5_command() {
        let upto_1_5 = COMMANDS.iter().filter(|c| c.version <= "1.5").count();
        assert_eq!(upto_1_5, 452);
        let lightfv = Command::find("glLightfv").expect("glLightfv");
        assert_eq!(
            lightfv.c_prototype(),
            "void glLightfv(GLenum light, GLenum pname, const GLfloat *params)"
        );
        assert_eq!(lightfv.count, Some("light"));
        assert_eq!(Command::find("glEnd").map(|c| c.inside), Some(true));
        assert_eq!(Command::find("glGenLists").map(|c| c.ret), Some("GLuint"));
    }

    #[test]
    fn every_call_has_a_row() {
        for name in crate::call::NAMES {
            let row = Command::find(&format!("gl{name}"));
            let winsys = crate::call::WINSYS.contains(name);
            assert_eq!(row.is_some_and(|c| c.method.is_some()), !winsys, "{name}");
        }
        let implemented = COMMANDS.iter().filter(|c| c.method.is_some()).count();
        assert_eq!(
            implemented,
            crate::call::NAMES.len() - crate::call::WINSYS.len()
        );
    }
}
