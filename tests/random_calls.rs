//! Property test: thousands of random call sequences (valid and invalid enums, NaN, infinities,
//! extremes, Begin/End misuse) run through `Context::execute`. Checks that nothing panics, that
//! the error flag only ever holds a GL error code, that a call which raised an error left the
//! State unchanged, and that between Begin and End every command GL 2.1 §2.6.3 does not list is
//! INVALID_OPERATION and changes nothing.

mod common;

use fixedgl::state::State;
use fixedgl::{gl, Call, Context};
use proptest::prelude::*;

/// The codes `glGetError` may return (GL 2.1 table 2.3).
const CODES: [u32; 7] = [
    gl::NO_ERROR,
    gl::INVALID_ENUM,
    gl::INVALID_VALUE,
    gl::INVALID_OPERATION,
    gl::STACK_OVERFLOW,
    gl::STACK_UNDERFLOW,
    gl::OUT_OF_MEMORY,
];

/// State equality where NaN equals NaN (a NaN a valid call stored must not fail the check).
fn same(a: &State, b: &State) -> bool {
    a == b || format!("{a:?}") == format!("{b:?}")
}

/// The commands GL 2.1 §2.6.3 allows between Begin and End (of the variants generated here).
fn allowed_inside(call: &Call) -> bool {
    let name = format!("{call:?}");
    [
        "Vertex",
        "Normal",
        "Color",
        "SecondaryColor",
        "TexCoord",
        "MultiTexCoord",
        "FogCoord",
        "EdgeFlag",
        "Material",
        "End",
        "CallList",
        // --- arrays
        "ArrayElement",
    ]
    .iter()
    .any(|p| {
        name.starts_with(p)
            && !name.starts_with("ColorMaterial")
            && !name.starts_with("ColorMask")
            // --- arrays: the *Pointer commands are not allowed inside.
            && !name.contains("Pointer(")
    })
}

fn run(calls: &[Call]) -> Result<(), TestCaseError> {
    let mut ctx = Context::new(16, 16).map_err(|e| TestCaseError::fail(e.to_string()))?;
    let mut inside = false;
    // lists: the list being defined and its mode (a model of NewList/EndList, GL 2.1 §5.4).
    let mut compiling: Option<u32> = None;
    for call in calls {
        // Lists never call lists here: a list calling itself twice would run 2^64 times (as in
        // GL). Nesting is tested in tests/lists.rs.
        if compiling.is_some() && matches!(call, Call::CallList(_) | Call::CallLists(..)) {
            continue;
        }
        let runs_list = matches!(call, Call::CallList(_) | Call::CallLists(..));
        let compile_only = compiling == Some(gl::COMPILE) && !call.executes_immediately();
        let e0 = ctx.pending_error();
        let before = ctx.state().clone();
        ctx.execute(call);
        let e1 = ctx.pending_error();
        prop_assert!(CODES.contains(&e1), "{call:?} left error {e1:#x}");
        if compile_only {
            // Stored, not executed: no error, no change (GL 2.1 §5.4).
            prop_assert!(
                same(&before, ctx.state()),
                "compiled {call:?} changed state"
            );
            prop_assert_eq!(e1, e0, "compiled {:?} raised an error", call);
            continue;
        }
        if runs_list {
            // The list's own commands may change state and then raise an error: no model here
            // beyond the Begin/End phase, read back from the context.
            inside = ctx.inside_begin_end();
            if !inside {
                prop_assert_eq!(ctx.get_error(), e1);
            }
            continue;
        }
        if e0 == gl::NO_ERROR && e1 != gl::NO_ERROR {
            prop_assert!(
                same(&before, ctx.state()),
                "{call:?} raised {e1:#x} and changed state"
            );
        }
        if inside && !allowed_inside(call) {
            prop_assert!(
                same(&before, ctx.state()),
                "{call:?} inside Begin/End changed state"
            );
            prop_assert!(
                e1 != gl::NO_ERROR,
                "{call:?} inside Begin/End raised nothing"
            );
            if e0 == gl::NO_ERROR {
                prop_assert_eq!(e1, gl::INVALID_OPERATION, "{:?} inside Begin/End", call);
            }
        }
        // A model of the Begin/End phase (GL 2.1 §2.6.1).
        match *call {
            Call::Begin(mode) if !inside && mode <= gl::POLYGON => inside = true,
            Call::End if inside => inside = false,
            Call::NewList(n, mode)
                if !inside
                    && n != 0
                    && compiling.is_none()
                    && (mode == gl::COMPILE || mode == gl::COMPILE_AND_EXECUTE) =>
            {
                compiling = Some(mode)
            }
            Call::EndList if !inside => compiling = None,
            _ => {}
        }
        if !inside {
            prop_assert_eq!(ctx.get_error(), e1);
            prop_assert_eq!(ctx.pending_error(), gl::NO_ERROR);
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, ..ProptestConfig::default() })]

    #[test]
    fn random_sequences_never_panic_and_errors_change_nothing(
        calls in prop::collection::vec(common::any_call(), 1..60)
    ) {
        run(&calls)?;
    }
}
