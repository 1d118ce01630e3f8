//! One `identity` claim checked from the body of its TOML table: the verdict and the
//! certificate (or counterexample). Shared by the claim-language tests.

use casteljau::verify::check_claim;
use casteljau::verify::claims::parse_file;
use casteljau::verify::Verdict;
use std::path::Path;

pub fn check(body: &str) -> casteljau::Result<(Verdict, String)> {
    let f = parse_file(
        &format!("[[claim]]\nid = \"x\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\n{body}"),
        Path::new("test.toml"),
    )?;
    let out = check_claim(&f.claim[0], false)?;
    Ok((out.verdict, out.certificate))
}
