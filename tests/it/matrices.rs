//! Transformation entry points against closed-form matrices written out by hand (GL 2.1
//! §2.11.2; GLU 1.3 §4; the derivations of seed 004), to 1e-6.
//!
//! Matrices are written here in rows, as the spec prints them; `rows()` reads the current
//! one back through `get_doublev` (column-major) and transposes it.

use fixedgl::{gl, glu, Call, Context};

const EPS: f64 = 1e-6;

fn ctx() -> Context {
    match Context::new(64, 64) {
        Ok(c) => c,
        Err(e) => panic!("context: {e}"),
    }
}

/// The matrix `pname` in rows.
fn rows(ctx: &mut Context, pname: u32) -> [[f64; 4]; 4] {
    let mut m = [0.0; 16];
    ctx.get_doublev(pname, &mut m);
    let mut r = [[0.0; 4]; 4];
    for (j, col) in m.chunks(4).enumerate() {
        for (i, v) in col.iter().enumerate() {
            r[i][j] = *v;
        }
    }
    r
}

fn assert_rows(ctx: &mut Context, pname: u32, want: [[f64; 4]; 4]) {
    let got = rows(ctx, pname);
    for i in 0..4 {
        for j in 0..4 {
            assert!(
                (got[i][j] - want[i][j]).abs() <= EPS,
                "element ({i},{j}): got {} want {}\ngot  {got:?}\nwant {want:?}",
                got[i][j],
                want[i][j]
            );
        }
    }
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
}

const IDENTITY: [[f64; 4]; 4] = [
    [1.0, 0.0, 0.0, 0.0],
    [0.0, 1.0, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0],
    [0.0, 0.0, 0.0, 1.0],
];

#[test]
fn frustum_matches_closed_form() {
    let mut c = ctx();
    c.matrix_mode(gl::PROJECTION);
    // l=-1 r=2 b=-0.5 t=1.5 n=1 f=10: 2n/(r-l)=2/3, (r+l)/(r-l)=1/3, 2n/(t-b)=1,
    // (t+b)/(t-b)=1/2, -(f+n)/(f-n)=-11/9, -2fn/(f-n)=-20/9.
    c.frustum(-1.0, 2.0, -0.5, 1.5, 1.0, 10.0);
    assert_rows(
        &mut c,
        gl::PROJECTION_MATRIX,
        [
            [2.0 / 3.0, 0.0, 1.0 / 3.0, 0.0],
            [0.0, 1.0, 0.5, 0.0],
            [0.0, 0.0, -11.0 / 9.0, -20.0 / 9.0],
            [0.0, 0.0, -1.0, 0.0],
        ],
    );
    // The modelview is untouched.
    assert_rows(&mut c, gl::MODELVIEW_MATRIX, IDENTITY);
}

#[test]
fn ortho_matches_closed_form() {
    let mut c = ctx();
    c.matrix_mode(gl::PROJECTION);
    // l=-2 r=6 b=-1 t=3 n=0.5 f=4.5: 2/8, -(4/8); 2/4, -(2/4); -2/4, -(5/4).
    c.ortho(-2.0, 6.0, -1.0, 3.0, 0.5, 4.5);
    assert_rows(
        &mut c,
        gl::PROJECTION_MATRIX,
        [
            [0.25, 0.0, 0.0, -0.5],
            [0.0, 0.5, 0.0, -0.5],
            [0.0, 0.0, -0.5, -1.25],
            [0.0, 0.0, 0.0, 1.0],
        ],
    );
}

#[test]
fn ortho_2d_is_ortho_with_unit_depth() {
    let mut c = ctx();
    glu::ortho_2d(&mut c, 0.0, 4.0, 0.0, 2.0);
    // 2/4, -(4/4); 2/2, -(2/2); -2/2, -(0/2).
    assert_rows(
        &mut c,
        gl::MODELVIEW_MATRIX,
        [
            [0.5, 0.0, 0.0, -1.0],
            [0.0, 1.0, 0.0, -1.0],
            [0.0, 0.0, -1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
    );
}

#[test]
fn perspective_matches_closed_form() {
    let mut c = ctx();
    c.matrix_mode(gl::PROJECTION);
    // fovy 90: f = cot 45° = 1; aspect 2; near 1, far 3: (3+1)/(1-3) = -2, 2·3·1/(1-3) = -3.
    glu::perspective(&mut c, 90.0, 2.0, 1.0, 3.0);
    assert_rows(
        &mut c,
        gl::PROJECTION_MATRIX,
        [
            [0.5, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, -2.0, -3.0],
            [0.0, 0.0, -1.0, 0.0],
        ],
    );

    // fovy 60: f = cot 30° = √3; aspect 1.5; near 0.1, far 100.
    let mut c = ctx();
    glu::perspective(&mut c, 60.0, 1.5, 0.1, 100.0);
    let f = 3.0f64.sqrt();
    assert_rows(
        &mut c,
        gl::MODELVIEW_MATRIX,
        [
            [f / 1.5, 0.0, 0.0, 0.0],
            [0.0, f, 0.0, 0.0],
            [0.0, 0.0, -100.1 / 99.9, -20.0 / 99.9],
            [0.0, 0.0, -1.0, 0.0],
        ],
    );
}

#[test]
fn perspective_equals_the_matching_frustum() {
    // gluPerspective(fovy, a, n, f) is glFrustum(-a·t, a·t, -t, t, n, f), t = n·tan(fovy/2).
    let mut a = ctx();
    glu::perspective(&mut a, 50.0, 4.0 / 3.0, 2.0, 40.0);
    let t = 2.0 * 25.0f64.to_radians().tan();
    let mut b = ctx();
    b.frustum(-t * 4.0 / 3.0, t * 4.0 / 3.0, -t, t, 2.0, 40.0);
    let want = rows(&mut b, gl::MODELVIEW_MATRIX);
    assert_rows(&mut a, gl::MODELVIEW_MATRIX, want);
}

#[test]
fn look_at_matches_the_seed_derivation() {
    // Seed 004: w = (eye − center)/|…|, u = (up × w)/|…|, v = w × u, V = [u; v; w]·T(−eye).
    // eye (0,0,3) looking at the origin: w = z, u = x, v = y: a pure translation by −3 in z.
    let mut c = ctx();
    glu::look_at(&mut c, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    assert_rows(
        &mut c,
        gl::MODELVIEW_MATRIX,
        [
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, -3.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
    );

    // eye (3,0,0): w = (1,0,0), u = (0,1,0) × (1,0,0) = (0,0,−1), v = w × u = (0,1,0);
    // translation column: −u·eye = 0, −v·eye = 0, −w·eye = −3.
    let mut c = ctx();
    glu::look_at(&mut c, 3.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    assert_rows(
        &mut c,
        gl::MODELVIEW_MATRIX,
        [
            [0.0, 0.0, -1.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [1.0, 0.0, 0.0, -3.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
    );

    // eye (1,1,1): w = (1,1,1)/√3, u = (1,0,−1)/√2, v = (−1,2,−1)/√6; −w·eye = −√3,
    // −u·eye = −v·eye = 0. The up vector (0,2,0) is not unit length: it must not matter.
    let mut c = ctx();
    glu::look_at(&mut c, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0);
    let (r2, r3, r6) = (2.0f64.sqrt(), 3.0f64.sqrt(), 6.0f64.sqrt());
    assert_rows(
        &mut c,
        gl::MODELVIEW_MATRIX,
        [
            [1.0 / r2, 0.0, -1.0 / r2, 0.0],
            [-1.0 / r6, 2.0 / r6, -1.0 / r6, 0.0],
            [1.0 / r3, 1.0 / r3, 1.0 / r3, -r3],
            [0.0, 0.0, 0.0, 1.0],
        ],
    );
}

#[test]
fn glu_goes_through_recorded_calls() {
    let mut c = ctx();
    c.start_recording();
    glu::look_at(&mut c, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    glu::perspective(&mut c, 90.0, 1.0, 1.0, 2.0);
    glu::ortho_2d(&mut c, 0.0, 1.0, 0.0, 1.0);
    let calls = c.stop_recording();
    let names: Vec<&str> = calls
        .iter()
        .map(|call| match call {
            Call::MultMatrixd(_) => "MultMatrixd",
            Call::Translated(..) => "Translated",
            Call::Ortho(..) => "Ortho",
            _ => "other",
        })
        .collect();
    assert_eq!(
        names,
        ["MultMatrixd", "Translated", "MultMatrixd", "Ortho"],
        "{calls:?}"
    );
    assert_eq!(calls[1], Call::Translated(-0.0, -0.0, -3.0));
    assert_eq!(
        calls[3],
        Call::Ortho(Box::new([0.0, 1.0, 0.0, 1.0, -1.0, 1.0]))
    );
}

#[test]
fn rotate_about_arbitrary_axes() {
    // 120° about (1,1,1) cycles the axes: x → y, y → z, z → x.
    let mut c = ctx();
    c.rotatef(120.0, 1.0, 1.0, 1.0);
    assert_rows(
        &mut c,
        gl::MODELVIEW_MATRIX,
        [
            [0.0, 0.0, 1.0, 0.0],
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
    );

    // 90° about z given as (0,0,2): the axis is normalised first. Seed's Rz(90°).
    let mut c = ctx();
    c.rotated(90.0, 0.0, 0.0, 2.0);
    assert_rows(
        &mut c,
        gl::MODELVIEW_MATRIX,
        [
            [0.0, -1.0, 0.0, 0.0],
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
    );

    // Seed's Ry(30°): [c 0 s; 0 1 0; −s 0 c], c = √3/2, s = 1/2.
    let mut c = ctx();
    c.rotatef(30.0, 0.0, 1.0, 0.0);
    let (cs, sn) = (3.0f64.sqrt() / 2.0, 0.5);
    assert_rows(
        &mut c,
        gl::MODELVIEW_MATRIX,
        [
            [cs, 0.0, sn, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [-sn, 0.0, cs, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
    );

    // Seed's Rx(−45°): [1 0 0; 0 c −s; 0 s c] with c = √2/2, s = −√2/2.
    let mut c = ctx();
    c.rotated(-45.0, 3.0, 0.0, 0.0);
    let h = 2.0f64.sqrt() / 2.0;
    assert_rows(
        &mut c,
        gl::MODELVIEW_MATRIX,
        [
            [1.0, 0.0, 0.0, 0.0],
            [0.0, h, h, 0.0],
            [0.0, -h, h, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
    );

    // A zero axis defines no rotation: the matrix is left as it was, and no error.
    let mut c = ctx();
    c.translatef(1.0, 0.0, 0.0);
    c.rotatef(45.0, 0.0, 0.0, 0.0);
    let mut want = IDENTITY;
    want[0][3] = 1.0;
    assert_rows(&mut c, gl::MODELVIEW_MATRIX, want);
}

#[test]
fn translate_and_scale_post_multiply() {
    // T(1,2,3)·S(2,3,4): the scale applies first to the vertex.
    let mut c = ctx();
    c.translatef(1.0, 2.0, 3.0);
    c.scalef(2.0, 3.0, 4.0);
    assert_rows(
        &mut c,
        gl::MODELVIEW_MATRIX,
        [
            [2.0, 0.0, 0.0, 1.0],
            [0.0, 3.0, 0.0, 2.0],
            [0.0, 0.0, 4.0, 3.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
    );
    // S(2,3,4)·T(1,2,3): the translation is scaled.
    let mut c = ctx();
    c.scaled(2.0, 3.0, 4.0);
    c.translated(1.0, 2.0, 3.0);
    assert_rows(
        &mut c,
        gl::MODELVIEW_MATRIX,
        [
            [2.0, 0.0, 0.0, 2.0],
            [0.0, 3.0, 0.0, 6.0],
            [0.0, 0.0, 4.0, 12.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
    );
}

/// 1..=16 in rows: a matrix whose every element differs, so a transposition shows.
const ROWS_1_16: [[f64; 4]; 4] = [
    [1.0, 2.0, 3.0, 4.0],
    [5.0, 6.0, 7.0, 8.0],
    [9.0, 10.0, 11.0, 12.0],
    [13.0, 14.0, 15.0, 16.0],
];

#[test]
fn load_and_transpose_forms() {
    let row_major: [f64; 16] = std::array::from_fn(|k| (k + 1) as f64);
    let row_major_f: [f32; 16] = std::array::from_fn(|k| (k + 1) as f32);
    // Column-major storage of ROWS_1_16: column j is (j+1, j+5, j+9, j+13).
    let col_major: [f64; 16] = std::array::from_fn(|k| (1 + k / 4 + 4 * (k % 4)) as f64);
    let col_major_f = col_major.map(|x| x as f32);

    let mut c = ctx();
    c.load_matrixd(&col_major);
    assert_rows(&mut c, gl::MODELVIEW_MATRIX, ROWS_1_16);
    c.load_matrixf(&col_major_f);
    assert_rows(&mut c, gl::MODELVIEW_MATRIX, ROWS_1_16);
    c.load_transpose_matrixd(&row_major);
    assert_rows(&mut c, gl::MODELVIEW_MATRIX, ROWS_1_16);
    c.load_transpose_matrixf(&row_major_f);
    assert_rows(&mut c, gl::MODELVIEW_MATRIX, ROWS_1_16);

    // TRANSPOSE_MODELVIEW_MATRIX returns the rows in memory order: 1, 2, 3, ...
    let mut t = [0.0f64; 16];
    c.get_doublev(gl::TRANSPOSE_MODELVIEW_MATRIX, &mut t);
    assert_eq!(t, row_major);

    // Mult forms, from a diagonal: diag(1,2,3,4)·M scales row i by i+1.
    let scaled = [
        [1.0, 2.0, 3.0, 4.0],
        [10.0, 12.0, 14.0, 16.0],
        [27.0, 30.0, 33.0, 36.0],
        [52.0, 56.0, 60.0, 64.0],
    ];
    let diag = [
        1.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0, 4.0,
    ];
    for form in 0..4 {
        let mut c = ctx();
        c.load_matrixd(&diag);
        match form {
            0 => c.mult_matrixd(&col_major),
            1 => c.mult_matrixf(&col_major_f),
            2 => c.mult_transpose_matrixd(&row_major),
            _ => c.mult_transpose_matrixf(&row_major_f),
        }
        assert_rows(&mut c, gl::MODELVIEW_MATRIX, scaled);
    }
}

#[test]
fn load_identity_resets_only_the_current_stack() {
    let mut c = ctx();
    c.translatef(1.0, 2.0, 3.0);
    c.matrix_mode(gl::PROJECTION);
    c.scalef(2.0, 2.0, 2.0);
    c.load_identity();
    assert_rows(&mut c, gl::PROJECTION_MATRIX, IDENTITY);
    let mut want = IDENTITY;
    want[0][3] = 1.0;
    want[1][3] = 2.0;
    want[2][3] = 3.0;
    assert_rows(&mut c, gl::MODELVIEW_MATRIX, want);
}

#[test]
fn push_pop_round_trip() {
    let mut c = ctx();
    c.translatef(1.0, 2.0, 3.0);
    let before = rows(&mut c, gl::MODELVIEW_MATRIX);
    c.push_matrix();
    let mut depth = [0i32];
    c.get_integerv(gl::MODELVIEW_STACK_DEPTH, &mut depth);
    assert_eq!(depth, [2]);
    // Push duplicates: the new top equals the old one until changed.
    assert_rows(&mut c, gl::MODELVIEW_MATRIX, before);
    c.rotatef(33.0, 1.0, 2.0, 3.0);
    c.scalef(5.0, 5.0, 5.0);
    c.pop_matrix();
    assert_rows(&mut c, gl::MODELVIEW_MATRIX, before);
    c.get_integerv(gl::MODELVIEW_STACK_DEPTH, &mut depth);
    assert_eq!(depth, [1]);
}

/// Pushes to the limit, one push too many, pops to the bottom, one pop too many.
fn check_stack_limit(c: &mut Context, depth_pname: u32, max: i32) {
    let mut depth = [0i32];
    for _ in 1..max {
        c.push_matrix();
    }
    assert_eq!(c.get_error(), gl::NO_ERROR);
    c.get_integerv(depth_pname, &mut depth);
    assert_eq!(depth, [max]);
    c.push_matrix();
    assert_eq!(c.get_error(), gl::STACK_OVERFLOW);
    c.get_integerv(depth_pname, &mut depth);
    assert_eq!(depth, [max]);
    for _ in 1..max {
        c.pop_matrix();
    }
    assert_eq!(c.get_error(), gl::NO_ERROR);
    c.pop_matrix();
    assert_eq!(c.get_error(), gl::STACK_UNDERFLOW);
    c.get_integerv(depth_pname, &mut depth);
    assert_eq!(depth, [1]);
}

#[test]
fn stack_limits_for_every_stack() {
    let mut c = ctx();
    let mut max = [0i32];
    c.get_integerv(gl::MAX_MODELVIEW_STACK_DEPTH, &mut max);
    assert_eq!(max, [32]);
    check_stack_limit(&mut c, gl::MODELVIEW_STACK_DEPTH, 32);

    c.matrix_mode(gl::PROJECTION);
    c.get_integerv(gl::MAX_PROJECTION_STACK_DEPTH, &mut max);
    assert_eq!(max, [32]);
    check_stack_limit(&mut c, gl::PROJECTION_STACK_DEPTH, 32);

    c.matrix_mode(gl::TEXTURE);
    c.get_integerv(gl::MAX_TEXTURE_STACK_DEPTH, &mut max);
    assert_eq!(max, [10]);
    for unit in 0..4 {
        c.active_texture(gl::TEXTURE0 + unit);
        check_stack_limit(&mut c, gl::TEXTURE_STACK_DEPTH, 10);
    }
}

#[test]
fn texture_stacks_are_per_unit() {
    let mut c = ctx();
    c.matrix_mode(gl::TEXTURE);
    c.active_texture(gl::TEXTURE2);
    c.push_matrix();
    c.translatef(0.5, 0.0, 0.0);
    let mut depth = [0i32];
    c.get_integerv(gl::TEXTURE_STACK_DEPTH, &mut depth);
    assert_eq!(depth, [2]);
    let mut want = IDENTITY;
    want[0][3] = 0.5;
    assert_rows(&mut c, gl::TEXTURE_MATRIX, want);

    c.active_texture(gl::TEXTURE0);
    c.get_integerv(gl::TEXTURE_STACK_DEPTH, &mut depth);
    assert_eq!(depth, [1]);
    assert_rows(&mut c, gl::TEXTURE_MATRIX, IDENTITY);
    assert_rows(&mut c, gl::MODELVIEW_MATRIX, IDENTITY);
    assert_eq!(c.state().texture_matrix[2].depth(), 2);
}

fn plane(c: &mut Context, p: u32) -> [f64; 4] {
    let mut eq = [f64::NAN; 4];
    c.get_clip_plane(p, &mut eq);
    eq
}

fn assert_plane(got: [f64; 4], want: [f64; 4]) {
    for k in 0..4 {
        assert!((got[k] - want[k]).abs() <= EPS, "got {got:?} want {want:?}");
    }
}

#[test]
fn clip_plane_is_stored_in_eye_coordinates() {
    let mut c = ctx();
    // Object z >= 0 under a translation by −5 in z is eye z + 5 >= 0.
    c.translatef(0.0, 0.0, -5.0);
    c.clip_plane(gl::CLIP_PLANE0, &[0.0, 0.0, 1.0, 0.0]);
    assert_plane(plane(&mut c, gl::CLIP_PLANE0), [0.0, 0.0, 1.0, 5.0]);

    // Object x >= 0 under a 90° rotation about z (object x is eye y) is eye y >= 0.
    c.load_identity();
    c.rotatef(90.0, 0.0, 0.0, 1.0);
    c.clip_plane(gl::CLIP_PLANE3, &[1.0, 0.0, 0.0, 0.0]);
    assert_plane(plane(&mut c, gl::CLIP_PLANE3), [0.0, 1.0, 0.0, 0.0]);

    // Object x >= 1 under a uniform scale by 2 is eye x >= 2: 0.5·x − 1 >= 0.
    c.load_identity();
    c.scalef(2.0, 2.0, 2.0);
    c.clip_plane(gl::CLIP_PLANE5, &[1.0, 0.0, 0.0, -1.0]);
    assert_plane(plane(&mut c, gl::CLIP_PLANE5), [0.5, 0.0, 0.0, -1.0]);

    // Later modelview changes do not move stored planes; the projection never applies.
    c.translatef(7.0, 7.0, 7.0);
    assert_plane(plane(&mut c, gl::CLIP_PLANE0), [0.0, 0.0, 1.0, 5.0]);
    c.load_identity();
    c.matrix_mode(gl::PROJECTION);
    c.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
    c.clip_plane(gl::CLIP_PLANE1, &[1.0, 2.0, 3.0, 4.0]);
    assert_plane(plane(&mut c, gl::CLIP_PLANE1), [1.0, 2.0, 3.0, 4.0]);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

#[test]
fn viewport_and_depth_range_clamp() {
    let mut c = ctx();
    c.viewport(-10, 20, 100_000, 30);
    let mut v = [0i32; 4];
    c.get_integerv(gl::VIEWPORT, &mut v);
    assert_eq!(v, [-10, 20, 16384, 30]);

    c.depth_range(-0.5, 2.0);
    let mut d = [0.0f64; 2];
    c.get_doublev(gl::DEPTH_RANGE, &mut d);
    assert_eq!(d, [0.0, 1.0]);
    // near > far is allowed.
    c.depth_range(0.75, 0.25);
    c.get_doublev(gl::DEPTH_RANGE, &mut d);
    assert_eq!(d, [0.75, 0.25]);
    assert_eq!(c.get_error(), gl::NO_ERROR);
}

#[test]
fn replaying_a_recording_reproduces_the_state() {
    let mut a = ctx();
    a.start_recording();
    a.matrix_mode(gl::PROJECTION);
    glu::perspective(&mut a, 45.0, 1.0, 0.1, 50.0);
    a.matrix_mode(gl::MODELVIEW);
    glu::look_at(&mut a, 1.0, 2.0, 3.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    a.push_matrix();
    a.rotatef(10.0, 0.0, 1.0, 0.0);
    a.translated(1.0, 0.0, 0.0);
    a.scalef(1.0, 2.0, 1.0);
    a.mult_transpose_matrixf(&[1.0; 16]);
    a.clip_plane(gl::CLIP_PLANE2, &[0.0, 1.0, 0.0, 0.5]);
    a.viewport(1, 2, 30, 40);
    a.depth_range(0.25, 0.5);
    a.active_texture(gl::TEXTURE1);
    a.client_active_texture(gl::TEXTURE3);
    a.matrix_mode(gl::TEXTURE);
    a.load_transpose_matrixd(&[2.0; 16]);
    a.ortho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
    a.frustum(-1.0, 1.0, -1.0, 1.0, 0.0, 1.0); // INVALID_VALUE, replayed too
    let calls = a.stop_recording();
    assert_eq!(calls.len(), 19);

    let mut b = ctx();
    b.replay(&calls);
    assert_eq!(a.state(), b.state());
    assert_eq!(a.get_error(), gl::INVALID_VALUE);
    assert_eq!(b.get_error(), gl::INVALID_VALUE);
}

/// GL 2.1 §2.14.1: POSITION is transformed by the modelview current at the call, SPOT_DIRECTION by
/// its upper 3x3; later modelview changes do not move them. Worked by hand: M = T(1,2,3)·Rz(90°),
/// Rz(90°) maps (1,0,0) to (0,1,0), so the point (1,0,0,1) goes to (0,1,0)+(1,2,3) = (1,3,3,1), the
/// direction (1,0,0,0) to (0,1,0,0), and the spot direction (1,0,0) to (0,1,0).
#[test]
fn light_position_and_spot_direction_are_stored_in_eye_coordinates() {
    let mut c = ctx();
    c.matrix_mode(gl::MODELVIEW);
    c.translatef(1.0, 2.0, 3.0);
    c.rotatef(90.0, 0.0, 0.0, 1.0);
    c.lightfv(gl::LIGHT1, gl::POSITION, &[1.0, 0.0, 0.0, 1.0]);
    c.lightfv(gl::LIGHT2, gl::POSITION, &[1.0, 0.0, 0.0, 0.0]);
    c.lightfv(gl::LIGHT1, gl::SPOT_DIRECTION, &[1.0, 0.0, 0.0]);
    c.load_identity();
    assert_eq!(c.get_error(), gl::NO_ERROR);

    let mut got = [0.0f32; 4];
    c.get_lightfv(gl::LIGHT1, gl::POSITION, &mut got);
    assert_close(&got, &[1.0, 3.0, 3.0, 1.0]);
    c.get_lightfv(gl::LIGHT2, gl::POSITION, &mut got);
    assert_close(&got, &[0.0, 1.0, 0.0, 0.0]);
    let mut dir = [0.0f32; 3];
    c.get_lightfv(gl::LIGHT1, gl::SPOT_DIRECTION, &mut dir);
    assert_close(&dir, &[0.0, 1.0, 0.0]);
}

fn assert_close(got: &[f32], want: &[f32]) {
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() < 1e-6, "got {got:?}, want {want:?}");
    }
}
