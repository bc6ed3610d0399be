//! How much faster than real time the averaged-PWM plant runs with the
//! firmware core in the loop while flying 11 Hz, +-30 deg (target: >= 200x
//! on one core, i.e. <= 0.5 ms per simulated 0.1 s).

use criterion::{criterion_group, criterion_main, Criterion};
use fwav_actuator::params::PlantParams;
use fwav_hil_sim::scenario::{HostLink, Scenario};
use fwav_hil_sim::sim::Simulator;
use fwav_protocol::{Command, Hello};

fn flying() -> (Simulator, HostLink) {
    let scenario = Scenario::from_toml(include_str!("../scenarios/cruise-11hz.toml"))
        .expect("shipped scenario");
    let profile = scenario.profile().expect("valid profile");
    let mut sim = Simulator::new(&PlantParams::default());
    let mut host = HostLink::default();
    for command in [
        Command::Handshake(Hello::THIS),
        Command::UploadProfile(profile),
        Command::Arm,
        Command::Start,
    ] {
        host.request(&mut sim, command);
    }
    for k in 0..20_000 {
        if k % 1000 == 0 {
            host.request(&mut sim, Command::Ping { nonce: k }); // heartbeat
        }
        sim.step(); // past the 1 s ramp
    }
    (sim, host)
}

fn realtime(c: &mut Criterion) {
    for (name, ledger) in [
        ("with energy ledger (hil-sim run)", true),
        ("without ledger (hil-sim serve)", false),
    ] {
        let (mut sim, mut host) = flying();
        sim.plant.keep_ledger = ledger;
        let steps = (0.1 / sim.params().control_dt()) as usize; // 0.1 s simulated
        c.bench_function(&format!("fly 0.1 s simulated, {name}"), |b| {
            b.iter(|| {
                host.request(&mut sim, Command::Ping { nonce: 0 }); // heartbeat
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
