//! The lemmas a certificate cites, resolved among the files checked together (as a
//! metamath or Lean checker resolves a theorem's references): a file whose proof assumes
//! lemma goals is accepted only when every lemma's file is among them, is itself accepted, and
//! states the same goal; the references must form no cycle.

use super::{hyper, Recheck};
use serde_json::Value as Json;
use std::collections::BTreeMap;

/// Where the resolution of a file stands.
#[derive(Clone)]
enum State {
    Open,
    /// On the path being resolved (a reference back to it closes a cycle).
    Visiting,
    Done(Recheck),
}

/// What resolving needs of one certificate (the rest of the file is not kept).
pub(super) struct Link {
    id: Option<String>,
    goal: Option<Json>,
    /// The lemmas it cites, each id and goal; or why they cannot be read.
    lemmas: Result<Vec<(String, Json)>, String>,
}

impl Link {
    /// The link of a certificate's JSON value (`None`: not JSON).
    pub(super) fn of(cert: Option<&Json>) -> Link {
        Link {
            id: cert
                .and_then(|c| c.get("id"))
                .and_then(Json::as_str)
                .map(str::to_string),
            goal: cert.and_then(|c| c.get("goal")).cloned(),
            lemmas: cert.map_or(Ok(Vec::new()), |c| {
                hyper::lemmas(c).map(|l| l.into_iter().map(|(id, g)| (id, g.clone())).collect())
            }),
        }
    }
}

/// The certificates `certs` with their results alone, `alone`, resolved together: the final
/// result of each.
pub(super) fn resolve(certs: &[Link], alone: Vec<Recheck>) -> Vec<Recheck> {
    let mut ids: BTreeMap<&str, Vec<usize>> = BTreeMap::new();
    for (i, c) in certs.iter().enumerate() {
        if let Some(id) = &c.id {
            ids.entry(id.as_str()).or_default().push(i);
        }
    }
    let mut r = Resolver {
        certs,
        alone,
        ids,
        state: vec![State::Open; certs.len()],
        path: Vec::new(),
    };
    (0..certs.len()).map(|i| r.result(i)).collect()
}

struct Resolver<'a> {
    certs: &'a [Link],
    alone: Vec<Recheck>,
    ids: BTreeMap<&'a str, Vec<usize>>,
    state: Vec<State>,
    /// The ids on the path being resolved, in order.
    path: Vec<String>,
}

impl Resolver<'_> {
    fn result(&mut self, i: usize) -> Recheck {
        match &self.state[i] {
            State::Done(r) => return r.clone(),
            State::Visiting => unreachable!("a cycle is caught before its file is entered again"),
            State::Open => {}
        }
        let out = self.resolve(i);
        self.state[i] = State::Done(out.clone());
        out
    }

    fn resolve(&mut self, i: usize) -> Recheck {
        let Recheck::Accepted(what) = &self.alone[i] else {
            return self.alone[i].clone();
        };
        let what = what.clone();
        let c = &self.certs[i];
        let lemmas = match &c.lemmas {
            Ok(l) => l,
            Err(e) => return Recheck::Refused(e.clone()),
        };
        if lemmas.is_empty() {
            return Recheck::Accepted(what);
        }
        self.state[i] = State::Visiting;
        self.path.push(c.id.clone().unwrap_or_default());
        let out = self.lemmas(lemmas, what);
        self.path.pop();
        out
    }

    /// The result of a file accepted alone (`what`) once its `lemmas` are resolved.
    fn lemmas(&mut self, lemmas: &[(String, Json)], what: String) -> Recheck {
        let mut missing: Option<Recheck> = None;
        for (id, goal) in lemmas {
            let files = self.ids.get(id.as_str()).cloned().unwrap_or_default();
            let j = match files[..] {
                [] => {
                    missing.get_or_insert(Recheck::NotChecked(format!(
                        "rests on lemma {id}, whose file was not given"
                    )));
                    continue;
                }
                [j] => j,
                _ => return Recheck::Refused(format!("lemma {id}: {} files state it", files.len())),
            };
            if matches!(self.state[j], State::Visiting) {
                let from = self.path.iter().position(|p| p == id).unwrap_or(0);
                let mut cycle = self.path[from..].to_vec();
                cycle.push(id.clone());
                return Recheck::Refused(format!("the lemmas form a cycle: {}", cycle.join(" → ")));
            }
            if self.certs[j].goal.as_ref() != Some(goal) {
                return Recheck::Refused(format!(
                    "lemma {id}: its file states another goal than the one this proof assumes"
                ));
            }
            match self.result(j) {
                Recheck::Accepted(_) => {}
                Recheck::NotChecked(why) => {
                    missing.get_or_insert(Recheck::NotChecked(format!(
                        "rests on lemma {id}, which is not re-checked ({why})"
                    )));
                }
                Recheck::Refused(why) => {
                    return Recheck::Refused(format!("rests on lemma {id}, which is refused ({why})"))
                }
            }
        }
        missing.unwrap_or_else(|| {
            let ids: Vec<&str> = lemmas.iter().map(|(id, _)| id.as_str()).collect();
            Recheck::Accepted(format!(
                "{what}; its lemmas {} re-checked in their own files, with the goals it assumes",
                ids.join(", ")
            ))
        })
    }
}
