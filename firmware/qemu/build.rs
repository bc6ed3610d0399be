//! Linker setup for the microcontroller build only: `memory.x` (the
//! emulated board's memory map) and cortex-m-rt's `link.x`. Nothing happens
//! for a host build. (The constants of the shipped plant and profile are
//! `src/shipped.rs`, generated and checked by a test, so this build needs
//! no host crates.)

use std::{env, fs, path::PathBuf};

fn main() {
    println!("cargo:rerun-if-changed=memory.x");
    println!("cargo:rerun-if-changed=build.rs");
    if env::var("CARGO_CFG_TARGET_OS").as_deref() != Ok("none") {
        return;
    }
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    fs::copy("memory.x", out.join("memory.x")).expect("memory.x is next to build.rs");
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rustc-link-arg-bins=--nmagic");
    println!("cargo:rustc-link-arg-bins=-Tlink.x");
}
