//! The `simulator` example's `--progressive DIR`, run as a user runs it: one PNG a pass, each
//! the picture the passes so far leave, the last the plain render's; `--spacing` chooses the
//! first pass, and bad values and combinations are refused without a panic.

#[path = "common/simulator.rs"]
mod simulator_run;

use std::path::{Path, PathBuf};

use simulator_run::simulator;

use fixray::{Framebuffer, Pass, Rgb, demo, render, render_pass, render_pass_row};

/// An empty directory of this test's own, which the example has to create.
fn temp_dir(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("simulator-progressive-{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// Runs the simulator, which must succeed, and returns what it printed.
fn run_ok(args: &[&str]) -> String {
    let out = simulator(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// Decodes an 8-bit RGB PNG: (width, height, RGB bytes).
fn decode(path: &Path) -> (u32, u32, Vec<u8>) {
    let file = std::fs::File::open(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let decoder = png::Decoder::new(std::io::BufReader::new(file));
    let mut reader = decoder.read_info().unwrap();
    let mut bytes = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut bytes).unwrap();
    assert_eq!(
        (info.color_type, info.bit_depth),
        (png::ColorType::Rgb, png::BitDepth::Eight)
    );
    bytes.truncate(info.buffer_size());
    (info.width, info.height, bytes)
}

/// The PNG files in `dir`, sorted.
fn files(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|entry| entry.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// Each pass's PNG is the core's framebuffer after the passes so far, its report line gives
/// the pass's spacing, the pixels `render_pass_row` traces for it and the file, and the last
/// PNG is the plain render.
#[test]
fn each_pass_is_written_and_the_last_is_the_plain_render() {
    const W: usize = 96;
    const H: usize = 64;
    let dir = temp_dir("default");
    let stdout = run_ok(&["--progressive", dir.to_str().unwrap(), "--size", "96x64"]);
    let lines: Vec<String> = stdout
        .lines()
        .map(|line| line.split_whitespace().collect::<Vec<_>>().join(" "))
        .collect();

    let (scene, camera) = (demo::scene(), demo::camera(W as u32, H as u32).unwrap());
    let mut frame = Box::new(Framebuffer::<W, H>::new());
    let mut row = [Rgb::BLACK; W];
    let passes: Vec<Pass> = Pass::sequence(8).unwrap().collect();
    assert_eq!(passes.len(), 4);
    for (number, &pass) in (1..).zip(&passes) {
        render_pass(&scene, &camera, pass, &mut frame).unwrap();
        let traced: usize = (0..H as u32)
            .map(|y| render_pass_row(&scene, &camera, pass, y, &mut row).unwrap())
            .sum();
        let line = format!(
            "pass {number}: spacing {}, traced {traced} px",
            pass.spacing()
        );
        let name = format!("pass-{number}.png");
        assert!(
            lines
                .iter()
                .any(|l| l.starts_with(&line) && l.ends_with(&name)),
            "no line '{line} ... {name}' in:\n{stdout}"
        );
        let (w, h, bytes) = decode(&dir.join(&name));
        assert_eq!((w as usize, h as usize), (W, H));
        assert!(
            bytes == frame.bytes().collect::<Vec<u8>>(),
            "{name} differs from the framebuffer after {number} passes"
        );
    }
    assert_eq!(
        files(&dir),
        ["pass-1.png", "pass-2.png", "pass-3.png", "pass-4.png"]
    );
    let mut full = Box::new(Framebuffer::<W, H>::new());
    render(&scene, &camera, &mut full).unwrap();
    assert!(frame == full, "the passes end on the plain render");
    assert!(
        stdout.contains("the last equals a plain render"),
        "{stdout}"
    );
}

/// `--spacing` sets the first pass, and the last PNG is written as `--png` writes the
/// picture, in every colour format (the dithered ones too).
#[test]
fn spacing_chooses_the_first_pass_and_the_last_is_the_png() {
    for (spacing, count) in [("1", 1), ("2", 3), ("32", 6), ("64", 7)] {
        let dir = temp_dir(&format!("spacing-{spacing}"));
        let stdout = run_ok(&[
            "--progressive",
            dir.to_str().unwrap(),
            "--spacing",
            spacing,
            "--size",
            "40x30",
        ]);
        let expected: Vec<String> = (1..=count).map(|n| format!("pass-{n}.png")).collect();
        assert_eq!(files(&dir), expected, "--spacing {spacing}:\n{stdout}");
        assert!(
            stdout.contains(&format!("spacing {spacing:>2}, traced")),
            "--spacing {spacing}:\n{stdout}"
        );
    }
    for color in ["rgb888", "rgb565", "gray8", "binary"] {
        let dir = temp_dir(&format!("classic-{color}"));
        let png = dir.with_extension("png");
        let common = ["--scene", "classic", "--size", "67x45", "--color", color];
        let mut args = vec!["--progressive", dir.to_str().unwrap(), "--spacing=16"];
        args.extend_from_slice(&common);
        run_ok(&args);
        let mut args = vec!["--png", png.to_str().unwrap()];
        args.extend_from_slice(&common);
        run_ok(&args);
        assert!(
            decode(&dir.join("pass-5.png")) == decode(&png),
            "{color}: the last pass's PNG differs from --png's"
        );
    }
}

#[test]
fn bad_spacings_and_combinations_are_refused_with_a_message_not_a_panic() {
    let dir = temp_dir("refused");
    let at = dir.to_str().unwrap();
    for (args, mentions) in [
        (&["--progressive", at, "--spacing", "0"][..], "'0'"),
        (&["--progressive", at, "--spacing", "3"][..], "'3'"),
        (&["--progressive", at, "--spacing", "128"][..], "'128'"),
        (&["--progressive", at, "--spacing", "65536"][..], "'65536'"),
        (&["--progressive", at, "--spacing", "-8"][..], "'-8'"),
        (&["--progressive", at, "--spacing", "eight"][..], "'eight'"),
        (&["--progressive", at, "--spacing"][..], "--spacing"),
        (&["--progressive"][..], "--progressive"),
        (&["--spacing", "8"][..], "--progressive"),
        (&["--progressive", at, "--frames", "3"][..], "--frames"),
        (&["--frames", "3", "--progressive", at][..], "--frames"),
        (&["--progressive", at, "--png-dir", at][..], "--png-dir"),
        (&["--progressive", at, "--apng", "x.png"][..], "--apng"),
        (&["--progressive", at, "--png", "x.png"][..], "--png"),
    ] {
        let out = simulator(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(mentions), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    }
    // Nothing was drawn, so nothing was created.
    assert!(!dir.exists());
    // A directory that cannot be made is an error too, exit 1, with the path in the message.
    let out = simulator(&["--progressive", "/proc/no/such/dir"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("/proc/no/such/dir"));
}
