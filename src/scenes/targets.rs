//! `texture-targets` (issue #14): the texture targets beyond 2D. Four panels:
//! - left, a 1D texture of contour lines on a lit height field: TexGen OBJECT_LINEAR maps the
//!   height to s, the 1D texture (mipmapped, LINEAR_MIPMAP_LINEAR, REPEAT) draws a dark line
//!   every 0.1 units of height over a colour ramp, MODULATE over the lighting;
//! - right, slices through a 3D texture (a 32³ procedural volume of nested shells, mipmapped with
//!   GENERATE_MIPMAP, trilinear LINEAR_MIPMAP_LINEAR, CLAMP_TO_EDGE in s and t, REPEAT in r):
//!   three quads at different depths and tilts, the r coordinate varying across the tilted ones.
//! - third, a reflective sphere: a cube map (six 64² faces, a sky gradient with a grid and a
//!   coloured horizon per face, LINEAR, CLAMP_TO_EDGE) looked up by TexGen REFLECTION_MAP in
//!   s, t and r, MODULATE over a lit sphere.
//!
//! - fourth, four texture units combined on one lit sphere (§3.8.15): unit 0 a mipmapped 2D
//!   checker from gluSphere's coordinates, MODULATE over the lighting; unit 1 a 1D texture of
//!   bright latitude lines on black by TexGen OBJECT_LINEAR on z, ADD; unit 2 the 3D volume by
//!   TexGen OBJECT_LINEAR in s, t and r, COMBINE MODULATE with RGB_SCALE 2; unit 3 the cube map
//!   by REFLECTION_MAP, COMBINE INTERPOLATE with the previous colour by the constant's alpha.

use crate::gl::*;
use crate::{glu, Context};

use super::{Scene, LECTURE};

/// The scenes of this module.
pub const SCENES: [Scene; 1] = [Scene {
    name: "texture-targets",
    summary: "Texturing: 1D and 3D targets — contour lines from a 1D texture (TexGen OBJECT_LINEAR) on a lit height field, \
              slices through a mipmapped 3D texture (trilinear, WRAP_R), a cube-mapped sphere (REFLECTION_MAP), \
              four units (2D, 1D, 3D, cube) combined on one sphere by MODULATE, ADD and COMBINE",
    tolerance: LECTURE,
    default_size: (1280, 320),
    draw: texture_targets,
    animate: None,
    config: super::DEFAULT_CONFIG,
}];

/// The height field: z of (x, y) in [-1, 1]².
fn height(x: f32, y: f32) -> f32 {
    0.35 * (2.2 * x).sin() * (1.8 * y).cos() + 0.25 * (-(x * x + y * y) * 2.0).exp()
}

/// Its normal.
fn normal(x: f32, y: f32) -> [f32; 3] {
    let e = 1e-3;
    let dx = (height(x + e, y) - height(x - e, y)) / (2.0 * e);
    let dy = (height(x, y + e) - height(x, y - e)) / (2.0 * e);
    let n = [-dx, -dy, 1.0];
    let l = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    n.map(|c| c / l)
}

/// The contour texture's level of `w` texels: a colour ramp with a dark line at texel 0.
fn contour_level(w: usize) -> Vec<u8> {
    (0..w)
        .flat_map(|i| {
            let f = i as f32 / w as f32;
            let line = i * 16 / w == 0;
            if line {
                [30u8, 20, 10, 255]
            } else {
                [
                    (120.0 + 130.0 * f) as u8,
                    (230.0 - 90.0 * f) as u8,
                    (90.0 + 60.0 * (1.0 - f)) as u8,
                    255,
                ]
            }
        })
        .collect()
}

/// The 3D texture's base level: nested spherical shells around the centre, coloured by radius,
/// with a checker of the octants.
fn volume(n: usize) -> Vec<u8> {
    let mut out = Vec::with_capacity(n * n * n * 4);
    for k in 0..n {
        for j in 0..n {
            for i in 0..n {
                let c = |v: usize| (v as f32 + 0.5) / n as f32 - 0.5;
                let (x, y, z) = (c(i), c(j), c(k));
                let r = (x * x + y * y + z * z).sqrt();
                let shell = ((r * 10.0) as i32) % 2 == 0;
                let octant = ((x > 0.0) ^ (y > 0.0) ^ (z > 0.0)) as u8;
                let px = if shell {
                    [230, (80.0 + 300.0 * r) as u8, 40 + 120 * octant, 255]
                } else {
                    [40 + 100 * octant, 60, (250.0 - 200.0 * r) as u8, 255]
                };
                out.extend_from_slice(&px);
            }
        }
    }
    out
}

fn texture_targets(gl: &mut Context) {
    gl.clear_color(0.08, 0.08, 0.12, 1.0);
    gl.clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    gl.enable(DEPTH_TEST);
    let panels = super::shapes::panels(gl, 4, 1);
    let mut names = [0u32; 2];
    gl.gen_textures(2, &mut names);

    // The 1D contour texture: every level given (64 .. 1 texels).
    gl.bind_texture(TEXTURE_1D, names[0]);
    for level in 0..7 {
        let w = 64usize >> level;
        gl.tex_image_1d(
            TEXTURE_1D,
            level,
            RGBA as i32,
            w as i32,
            0,
            RGBA,
            UNSIGNED_BYTE,
            Some(&contour_level(w)),
        );
    }
    gl.tex_parameteri(TEXTURE_1D, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR as i32);
    gl.tex_parameteri(TEXTURE_1D, TEXTURE_MAG_FILTER, LINEAR as i32);

    // The 3D volume, mipmapped by GENERATE_MIPMAP.
    gl.bind_texture(TEXTURE_3D, names[1]);
    gl.tex_parameteri(TEXTURE_3D, GENERATE_MIPMAP, TRUE as i32);
    gl.tex_image_3d(
        TEXTURE_3D,
        0,
        RGBA as i32,
        32,
        32,
        32,
        0,
        RGBA,
        UNSIGNED_BYTE,
        Some(&volume(32)),
    );
    let mut cube = [0u32; 1];
    gl.gen_textures(1, &mut cube);
    gl.bind_texture(TEXTURE_CUBE_MAP, cube[0]);
    for face in 0..6u32 {
        gl.tex_image_2d(
            TEXTURE_CUBE_MAP_POSITIVE_X + face,
            0,
            RGB as i32,
            64,
            64,
            0,
            RGB,
            UNSIGNED_BYTE,
            Some(&cube_face(face, 64)),
        );
    }
    gl.tex_parameteri(TEXTURE_CUBE_MAP, TEXTURE_MIN_FILTER, LINEAR as i32);
    gl.tex_parameteri(TEXTURE_CUBE_MAP, TEXTURE_MAG_FILTER, LINEAR as i32);
    gl.tex_parameteri(TEXTURE_CUBE_MAP, TEXTURE_WRAP_S, CLAMP_TO_EDGE as i32);
    gl.tex_parameteri(TEXTURE_CUBE_MAP, TEXTURE_WRAP_T, CLAMP_TO_EDGE as i32);
    gl.tex_parameteri(TEXTURE_3D, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR as i32);
    gl.tex_parameteri(TEXTURE_3D, TEXTURE_MAG_FILTER, LINEAR as i32);
    gl.tex_parameteri(TEXTURE_3D, TEXTURE_WRAP_S, CLAMP_TO_EDGE as i32);
    gl.tex_parameteri(TEXTURE_3D, TEXTURE_WRAP_T, CLAMP_TO_EDGE as i32);
    gl.tex_parameteri(TEXTURE_3D, TEXTURE_WRAP_R, REPEAT as i32);

    let (x, y, w, h) = panels[0];
    gl.viewport(x, y, w, h);
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    glu::perspective(gl, 45.0, f64::from(w) / f64::from(h.max(1)), 0.5, 20.0);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    glu::look_at(gl, 0.0, -2.6, 2.2, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0);
    gl.enable(LIGHTING);
    gl.enable(LIGHT0);
    gl.lightfv(LIGHT0, POSITION, &[1.0, -1.0, 2.0, 0.0]);
    gl.lightfv(LIGHT0, DIFFUSE, &[0.9, 0.9, 0.9, 1.0]);
    gl.light_modelfv(LIGHT_MODEL_AMBIENT, &[0.35, 0.35, 0.35, 1.0]);
    gl.materialfv(FRONT_AND_BACK, AMBIENT_AND_DIFFUSE, &[1.0, 1.0, 1.0, 1.0]);
    gl.tex_geni(S, TEXTURE_GEN_MODE, OBJECT_LINEAR as i32);
    // s = 10·z + 0.5: a contour line every 0.1 of height.
    gl.tex_genfv(S, OBJECT_PLANE, &[0.0, 0.0, 10.0, 0.5]);
    gl.enable(TEXTURE_GEN_S);
    gl.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, MODULATE as i32);
    gl.enable(TEXTURE_1D);
    let n = 48;
    for j in 0..n {
        gl.begin(QUAD_STRIP);
        for i in 0..=n {
            for jj in [j + 1, j] {
                let px = -1.0 + 2.0 * i as f32 / n as f32;
                let py = -1.0 + 2.0 * jj as f32 / n as f32;
                let [nx, ny, nz] = normal(px, py);
                gl.normal3f(nx, ny, nz);
                gl.vertex3f(px, py, height(px, py));
            }
        }
        gl.end();
    }
    gl.disable(TEXTURE_1D);
    gl.disable(TEXTURE_GEN_S);
    gl.disable(LIGHTING);

    let (x, y, w, h) = panels[1];
    gl.viewport(x, y, w, h);
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    glu::perspective(gl, 45.0, f64::from(w) / f64::from(h.max(1)), 0.5, 20.0);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    glu::look_at(gl, 0.3, 0.8, 3.2, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    gl.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, REPLACE as i32);
    gl.enable(TEXTURE_3D);
    // Three slices: (centre x, tilt about y in degrees, r at the left and right edges).
    for (cx, tilt, r0, r1) in [
        (-0.9f32, 0.0f32, 0.5f32, 0.5f32),
        (0.0, 35.0, 0.1, 0.9),
        (0.9, -50.0, 0.7, 1.6),
    ] {
        gl.push_matrix();
        gl.translatef(cx, 0.0, 0.0);
        gl.rotatef(tilt, 0.0, 1.0, 0.0);
        gl.begin(QUADS);
        for (u, v) in [(0.0f32, 0.0f32), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            gl.tex_coord3f(u, v, r0 + (r1 - r0) * u);
            gl.vertex3f((u - 0.5) * 0.8, (v - 0.5) * 1.6, 0.0);
        }
        gl.end();
        gl.pop_matrix();
    }
    gl.disable(TEXTURE_3D);

    let (x, y, w, h) = panels[2];
    gl.viewport(x, y, w, h);
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    glu::perspective(gl, 40.0, f64::from(w) / f64::from(h.max(1)), 0.5, 20.0);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    glu::look_at(gl, 0.0, 0.6, 3.6, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    gl.enable(LIGHTING);
    gl.lightfv(LIGHT0, POSITION, &[-1.0, 1.5, 2.0, 0.0]);
    gl.materialfv(FRONT_AND_BACK, AMBIENT_AND_DIFFUSE, &[0.95, 0.95, 1.0, 1.0]);
    for coord in [S, T, R] {
        gl.tex_geni(coord, TEXTURE_GEN_MODE, REFLECTION_MAP as i32);
    }
    gl.enable(TEXTURE_GEN_S);
    gl.enable(TEXTURE_GEN_T);
    gl.enable(TEXTURE_GEN_R);
    gl.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, MODULATE as i32);
    gl.enable(TEXTURE_CUBE_MAP);
    gl.rotatef(20.0, 0.0, 1.0, 0.0);
    let mut q = glu::new_quadric();
    glu::sphere(gl, &mut q, 1.1, 48, 32);
    gl.disable(TEXTURE_CUBE_MAP);
    gl.disable(TEXTURE_GEN_S);
    gl.disable(TEXTURE_GEN_T);
    gl.disable(TEXTURE_GEN_R);
    gl.disable(LIGHTING);

    four_units(gl, panels[3], names[1], cube[0], &mut q);
}

/// The fourth panel: the four units combined on one sphere (see the module docs); `volume` the
/// 3D texture, `cube` the cube map.
fn four_units(
    gl: &mut Context,
    (x, y, w, h): (i32, i32, i32, i32),
    volume: u32,
    cube: u32,
    q: &mut glu::Quadric,
) {
    let mut more = [0u32; 2];
    gl.gen_textures(2, &mut more);
    gl.viewport(x, y, w, h);
    gl.matrix_mode(PROJECTION);
    gl.load_identity();
    glu::perspective(gl, 40.0, f64::from(w) / f64::from(h.max(1)), 0.5, 20.0);
    gl.matrix_mode(MODELVIEW);
    gl.load_identity();
    glu::look_at(gl, 0.0, 0.6, 3.6, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    gl.enable(LIGHTING);
    gl.lightfv(LIGHT0, POSITION, &[1.0, 1.5, 2.0, 0.0]);
    gl.materialfv(FRONT_AND_BACK, AMBIENT_AND_DIFFUSE, &[0.8, 0.8, 0.8, 1.0]);
    // The model: the sphere's poles along y, turned a little towards the viewer; TexGen's
    // object planes are in these coordinates.
    gl.rotatef(-70.0, 1.0, 0.0, 0.0);
    gl.rotatef(25.0, 0.0, 0.0, 1.0);

    // Unit 0: a mipmapped 2D checker (gluBuild2DMipmaps), MODULATE.
    gl.active_texture(TEXTURE0);
    gl.bind_texture(TEXTURE_2D, more[0]);
    let checker = crate::checkerboard(64, 8, [255, 255, 255, 255], [70, 70, 110, 255]);
    let _ = glu::build_2d_mipmaps(
        gl,
        TEXTURE_2D,
        RGBA as i32,
        64,
        64,
        RGBA,
        UNSIGNED_BYTE,
        &checker,
    );
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR as i32);
    gl.tex_parameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, LINEAR as i32);
    gl.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, MODULATE as i32);
    gl.enable(TEXTURE_2D);

    // Unit 1: bright lines on black (1D, mipmapped), ADD, every 0.2 of z.
    gl.active_texture(TEXTURE1);
    gl.bind_texture(TEXTURE_1D, more[1]);
    for level in 0..6 {
        let n = 32usize >> level;
        let line: Vec<u8> = (0..n)
            .flat_map(|i| {
                if i * 8 / n == 0 {
                    [90u8, 110, 160, 255]
                } else {
                    [0, 0, 0, 255]
                }
            })
            .collect();
        gl.tex_image_1d(
            TEXTURE_1D,
            level,
            RGBA as i32,
            n as i32,
            0,
            RGBA,
            UNSIGNED_BYTE,
            Some(&line),
        );
    }
    gl.tex_parameteri(TEXTURE_1D, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR as i32);
    gl.tex_parameteri(TEXTURE_1D, TEXTURE_MAG_FILTER, LINEAR as i32);
    gl.tex_geni(S, TEXTURE_GEN_MODE, OBJECT_LINEAR as i32);
    gl.tex_genfv(S, OBJECT_PLANE, &[0.0, 0.0, 5.0, 0.25]);
    gl.enable(TEXTURE_GEN_S);
    gl.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, ADD as i32);
    gl.enable(TEXTURE_1D);

    // Unit 2: the 3D volume at the object position (s, t, r = x, y, z scaled into the volume),
    // COMBINE MODULATE with the previous colour, RGB_SCALE 2.
    gl.active_texture(TEXTURE2);
    gl.bind_texture(TEXTURE_3D, volume);
    for (coord, gen, plane) in [
        (S, TEXTURE_GEN_S, [0.4f32, 0.0, 0.0, 0.5]),
        (T, TEXTURE_GEN_T, [0.0, 0.4, 0.0, 0.5]),
        (R, TEXTURE_GEN_R, [0.0, 0.0, 0.4, 0.5]),
    ] {
        gl.tex_geni(coord, TEXTURE_GEN_MODE, OBJECT_LINEAR as i32);
        gl.tex_genfv(coord, OBJECT_PLANE, &plane);
        gl.enable(gen);
    }
    gl.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, COMBINE as i32);
    gl.tex_envi(TEXTURE_ENV, COMBINE_RGB, MODULATE as i32);
    gl.tex_envi(TEXTURE_ENV, SOURCE0_RGB, TEXTURE as i32);
    gl.tex_envi(TEXTURE_ENV, SOURCE1_RGB, PREVIOUS as i32);
    gl.tex_envf(TEXTURE_ENV, RGB_SCALE, 2.0);
    gl.enable(TEXTURE_3D);

    // Unit 3: the environment by REFLECTION_MAP, COMBINE INTERPOLATE with the previous colour
    // by the constant's alpha 0.3.
    gl.active_texture(TEXTURE3);
    gl.bind_texture(TEXTURE_CUBE_MAP, cube);
    for (coord, gen) in [(S, TEXTURE_GEN_S), (T, TEXTURE_GEN_T), (R, TEXTURE_GEN_R)] {
        gl.tex_geni(coord, TEXTURE_GEN_MODE, REFLECTION_MAP as i32);
        gl.enable(gen);
    }
    gl.tex_envi(TEXTURE_ENV, TEXTURE_ENV_MODE, COMBINE as i32);
    gl.tex_envi(TEXTURE_ENV, COMBINE_RGB, INTERPOLATE as i32);
    gl.tex_envi(TEXTURE_ENV, SOURCE0_RGB, TEXTURE as i32);
    gl.tex_envi(TEXTURE_ENV, SOURCE1_RGB, PREVIOUS as i32);
    gl.tex_envi(TEXTURE_ENV, SOURCE2_RGB, CONSTANT as i32);
    gl.tex_envi(TEXTURE_ENV, OPERAND2_RGB, SRC_ALPHA as i32);
    gl.tex_envfv(TEXTURE_ENV, TEXTURE_ENV_COLOR, &[0.0, 0.0, 0.0, 0.3]);
    gl.enable(TEXTURE_CUBE_MAP);

    glu::quadric_texture(q, true);
    glu::sphere(gl, q, 1.1, 48, 32);
    glu::quadric_texture(q, false);

    for u in (0..4).rev() {
        gl.active_texture(TEXTURE0 + u);
        for t in [TEXTURE_1D, TEXTURE_2D, TEXTURE_3D, TEXTURE_CUBE_MAP] {
            gl.disable(t);
        }
        for g in [TEXTURE_GEN_S, TEXTURE_GEN_T, TEXTURE_GEN_R] {
            gl.disable(g);
        }
    }
    gl.disable(LIGHTING);
}

/// Face `face` (0 to 5: +X, -X, +Y, -Y, +Z, -Z) of the environment: a sky-to-ground gradient by
/// the face's t, a grid, and a colour of its own along the horizon.
fn cube_face(face: u32, n: usize) -> Vec<u8> {
    let tints: [[f32; 3]; 6] = [
        [1.0, 0.4, 0.3],
        [0.3, 1.0, 0.4],
        [0.6, 0.8, 1.0],
        [0.5, 0.35, 0.2],
        [1.0, 0.9, 0.3],
        [0.7, 0.4, 1.0],
    ];
    let tint = tints[face as usize % 6];
    let mut out = Vec::with_capacity(n * n * 3);
    for j in 0..n {
        for i in 0..n {
            let t = j as f32 / (n - 1) as f32;
            let grid = i % 16 == 0 || j % 16 == 0;
            let band = (t - 0.5).abs() < 0.08;
            let c = if grid {
                [0.1, 0.1, 0.15]
            } else if band {
                tint
            } else {
                [0.35 + 0.5 * t, 0.5 + 0.4 * t, 0.9 - 0.2 * t]
            };
            out.extend(c.map(|v| (v.clamp(0.0, 1.0) * 255.0) as u8));
        }
    }
    out
}
