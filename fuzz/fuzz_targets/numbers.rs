//! The numeric list parser of the command line (`--w 3.5,0,1`): a list is either refused
//! with an error naming its flag, or has exactly the asked count of finite numbers.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    for n in 1..=6 {
        match impax_cli::input::parse_numbers("w", text, n, "W") {
            Ok(v) => {
                assert_eq!(v.len(), n);
                assert!(v.iter().all(|x| x.is_finite()), "{text:?} → {v:?}");
            }
            Err(e) => assert!(e.message.starts_with("--w: "), "{}", e.message),
        }
    }
});
