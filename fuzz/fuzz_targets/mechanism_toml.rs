//! Mechanism files (`mechanism = "double-pendulum"` and the built-ins' parameters) as
//! `impax compare`, `impax audit` and `impax conserved` read them: exit 2 with one error
//! line, or a document without a non-finite number (`impax_cli::contract`).
#![no_main]

use libfuzzer_sys::fuzz_target;
use std::io::Write;

fuzz_target!(|data: &[u8]| {
    let path =
        std::env::temp_dir().join(format!("impax-fuzz-mechanism-{}.toml", std::process::id()));
    let mut file = std::fs::File::create(&path).expect("temporary file");
    file.write_all(data).expect("temporary file");
    drop(file);
    let p = path.to_str().expect("UTF-8 path");
    for args in [
        vec!["impax", "compare", p, "--json"],
        vec!["impax", "audit", p, "--json"],
        vec![
            "impax",
            "conserved",
            p,
            "--json",
            "--duration",
            "0.05",
            "--samples",
            "5",
        ],
    ] {
        let run = impax_cli::invoke(&args);
        if let Err(why) = impax_cli::contract::check(&run) {
            panic!("{args:?} on {:?}: {why}", String::from_utf8_lossy(data));
        }
    }
});
