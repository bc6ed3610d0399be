//! How much faster than real time the averaged-PWM plant runs with the
//! firmware core in the loop while flying 11 Hz, +-30 deg (target: >= 200x
//! on one core, i.e. <= 0.5 ms per simulated 0.1 s).

use criterion::{criterion_group, criterion_main, Criterion};
use fwav_actuator::params::PlantParams;
use fwav_hil_sim::scenario::Scenario;
use fwav_hil_sim::sim::Simulator;
use fwav_link::Link;
use fwav_protocol::Command;

fn flying() -> (Link<Simulator>, u32) {
    let scenario = Scenario::from_toml(include_str!("../scenarios/cruise-11hz.toml"))
        .expect("shipped scenario");
    let profile = scenario.profile().expect("valid profile");
    let mut host = Link::new(Simulator::new(&PlantParams::default()));
    host.handshake().expect("handshake");
    host.command(Command::UploadProfile(profile))
        .expect("accepted");
    let session = host.arm().expect("armed");
    host.command(Command::Start).expect("started");
    for k in 0..20_000 {
        if k % 1000 == 0 {
            host.heartbeat(session).expect("acked");
        }
        host.get_mut().step(); // past the 1 s ramp
    }
    (host, session)
}

fn realtime(c: &mut Criterion) {
    for (name, ledger) in [
        ("with energy ledger (hil-sim run)", true),
        ("without ledger (hil-sim serve)", false),
    ] {
        let (mut host, session) = flying();
        host.get_mut().plant.keep_ledger = ledger;
        let steps = (0.1 / host.get_ref().params().control_dt()) as usize; // 0.1 s simulated
        c.bench_function(&format!("fly 0.1 s simulated, {name}"), |b| {
            b.iter(|| {
                host.heartbeat(session).expect("acked");
                let sim = host.get_mut();
                for _ in 0..steps {
                    std::hint::black_box(sim.step());
                }
                assert!(sim.fc.is_running());
            })
        });
    }
}

criterion_group!(benches, realtime);
criterion_main!(benches);
