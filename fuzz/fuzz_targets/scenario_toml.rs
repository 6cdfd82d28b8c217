//! Scenario files as `impax compare FILE --json` and `impax simulate FILE --json` read them
//! (planar and `space = "3d"` bodies, mechanism files, simulation scenarios): every text is
//! either refused with exit 2 and one error line, or gives a document without a non-finite
//! number (`impax_cli::contract`).
#![no_main]

use libfuzzer_sys::fuzz_target;
use std::io::Write;

fuzz_target!(|data: &[u8]| {
    let path =
        std::env::temp_dir().join(format!("impax-fuzz-scenario-{}.toml", std::process::id()));
    let mut file = std::fs::File::create(&path).expect("temporary file");
    file.write_all(data).expect("temporary file");
    drop(file);
    let p = path.to_str().expect("UTF-8 path");
    for args in [
        vec!["impax", "compare", p, "--json"],
        vec![
            "impax",
            "simulate",
            p,
            "--json",
            "--until",
            "0.2",
            "--samples",
            "20",
        ],
    ] {
        let run = impax_cli::invoke(&args);
        if let Err(why) = impax_cli::contract::check(&run) {
            panic!("{args:?} on {:?}: {why}", String::from_utf8_lossy(data));
        }
    }
});
