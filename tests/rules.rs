//! The rules ARCHITECTURE.md sets for the code itself, checked on the source: the plain path
//! stays plain, chips are named in one place, and inline attributes stay few, each with its
//! reason.

use std::fs;
use std::path::{Path, PathBuf};

/// Every `.rs` file under `src/`, with its text.
fn sources() -> Vec<(PathBuf, String)> {
    fn walk(dir: &Path, out: &mut Vec<(PathBuf, String)>) {
        for entry in fs::read_dir(dir).expect("src/ is readable") {
            let path = entry.expect("a directory entry").path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let text = fs::read_to_string(&path).expect("a source file is UTF-8");
                out.push((path, text));
            }
        }
    }
    let mut out = Vec::new();
    walk(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"), &mut out);
    assert!(out.len() > 40, "found only {} source files", out.len());
    out
}

/// The lines of `text` that are code, not comments.
fn code_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.lines()
        .enumerate()
        .filter(|(_, line)| !line.trim_start().starts_with("//"))
}

#[test]
fn the_plain_path_has_no_inline_attribute_and_no_cfg() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/render/trace.rs");
    let text = fs::read_to_string(path).unwrap();
    for (number, line) in code_lines(&text) {
        for banned in ["#[inline", "#[cold", "cfg(", "cfg!(", "cfg_attr", "chip::"] {
            assert!(
                !line.contains(banned),
                "render/trace.rs line {}: `{banned}` in the plain path: {line}",
                number + 1
            );
        }
    }
}

#[test]
fn chips_are_named_only_in_the_chip_module() {
    for (path, text) in sources() {
        if path.ends_with("chip.rs") {
            continue;
        }
        for (number, line) in code_lines(&text) {
            for banned in [
                "target_arch",
                "target_has_atomic",
                "target_feature",
                "fixray_chip",
            ] {
                assert!(
                    !line.contains(banned),
                    "{}:{}: `{banned}` outside src/chip.rs: {line}",
                    path.display(),
                    number + 1
                );
            }
        }
    }
}

#[test]
fn inline_attributes_are_few_and_each_says_why() {
    let mut count = 0;
    for (path, text) in sources() {
        let lines: Vec<&str> = text.lines().collect();
        for (i, line) in lines.iter().enumerate() {
            let line = line.trim();
            assert!(
                !(line.starts_with("#[cfg_attr") && line.contains("inline")),
                "{}:{}: an inline attribute chosen by target",
                path.display(),
                i + 1
            );
            if line != "#[inline(always)]" && line != "#[inline(never)]" {
                continue;
            }
            count += 1;
            // Its reason: a `//` comment among the lines just above it (past other attributes).
            let above = lines[..i]
                .iter()
                .rev()
                .map(|l| l.trim())
                .skip_while(|l| l.starts_with("#["))
                .take_while(|l| l.starts_with("//"))
                .any(|l| l.starts_with("// ") && !l.starts_with("///"));
            assert!(
                above,
                "{}:{}: {line} without a `//` comment saying what it saves",
                path.display(),
                i + 1
            );
        }
    }
    assert!(
        count <= 30,
        "{count} inline(always) and inline(never) attributes, more than 30"
    );
}
