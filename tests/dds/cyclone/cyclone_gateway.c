/* A minimal gateway on Cyclone DDS, written from docs/gateway.md and idl/tomc_gateway.idl alone (types by
 * Cyclone's idlc): the interop test of issue 16 (tests/dds/cyclone_interop_test.cpp). It serves ONE device
 * with PROFIdrive telegram 1 (STW1/NSOLL_A -> ZSW1/NIST_A, big-endian) whose "drive" is the PROFIdrive state
 * machine S1..S4 of spec 06 §4.2 and a speed that follows its setpoint at once.
 *
 *   cyclone_gateway DOMAIN PARTITION DEVICE SECONDS [xcdr2]
 *
 * `xcdr2` breaks the contract on purpose: the actual and status writers offer XCDR2 only, which a tomc
 * controller must report as "endpoints do not match" (docs/gateway.md §1, §8).
 * Network (docs/gateway.md §11, Appendix B): unicast only, on 127.0.0.1, SPDP to 127.0.0.1 for participant
 * indices 0..31; no multicast. The configuration is given in code (dds_create_domain), so no CYCLONEDDS_URI
 * in the environment can change it. It runs until SIGTERM/SIGINT or SECONDS have passed, then exits 0.
 *
 * The contract rules it follows: G1 one controller at a time (watchdog 1 s), G2 refusals, G3 telegram check,
 * G4 one answer per applied setpoint, G5 incarnation/sequence, G6/G7 idle answers once per 1 ms cycle, G8
 * status at start, on a change and every second, G9 probe answers. */
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "dds/dds.h"
#include "tomc_gateway.h"

#define CYCLE_NS 1000000LL       /* the gateway's own clock: 1 ms */
#define WATCHDOG_NS 1000000000LL /* G6: a controller silent for 1 s is released */
#define STATUS_PERIOD_NS 1000000000LL

static volatile sig_atomic_t stop_requested = 0;
static void on_signal(int s) {
  (void)s;
  stop_requested = 1;
}

static int64_t now_ns(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (int64_t)t.tv_sec * 1000000000LL + t.tv_nsec;
}

static uint64_t random_id(void) {
  uint64_t id = ((uint64_t)rand() << 33) ^ ((uint64_t)rand() << 11) ^ (uint64_t)now_ns();
  return id == 0 ? 1 : id;
}

/* ---- the drive: telegram 1 ---- */
enum { S1 = 1, S2, S3, S4 };
static int drive_state = S1;
static uint16_t stw1 = 0, nsoll = 0;

static void drive_step(void) {
  const int on = stw1 & 0x0001, no_off2 = stw1 & 0x0002, no_off3 = stw1 & 0x0004, enable = stw1 & 0x0008;
  if (!no_off2 || !no_off3) {
    drive_state = S1;
  } else if (drive_state == S1) {
    if (!on) drive_state = S2;
  } else if (!on) {
    drive_state = S2;
  } else if (drive_state == S2) {
    drive_state = S3;
  } else if (drive_state == S3 && enable) {
    drive_state = S4;
  } else if (drive_state == S4 && !enable) {
    drive_state = S3;
  }
}

static uint16_t zsw1(void) {
  uint16_t z = 0x0200;            /* bit 9: control requested */
  if (stw1 & 0x0002) z |= 0x0010; /* no OFF2 */
  if (stw1 & 0x0004) z |= 0x0020; /* no OFF3 */
  switch (drive_state) {
    case S1:
      z |= 0x0040;
      break;
    case S2:
      z |= 0x0001;
      break;
    case S3:
      z |= 0x0003;
      break;
    case S4:
      z |= 0x0107;
      break; /* bit 8: speed within tolerance: it follows at once */
  }
  return z;
}

static uint16_t nist(void) {
  return drive_state == S4 ? nsoll : 0;
}

/* ---- the gateway ---- */
static const char* device_name;
static const char* gateway_name = "cyclone-gw";
static uint64_t incarnation, sequence = 0, owner = 0, last_cycle = 0, setpoint_cycle = 0;
static int have_cycle = 0, has_setpoint = 0;
static int64_t last_setpoint_ns = 0;
static uint64_t applied = 0, gaps = 0, rejected = 0, published = 0;
static char mismatch[128] = "";
static dds_entity_t actual_writer, status_writer;

static unsigned char actual_pzd[4];
static void publish_answer(uint64_t controller, int probe) {
  tomc_gateway_DeviceActual device;
  memset(&device, 0, sizeof device);
  snprintf(device.device, sizeof device.device, "%s", device_name);
  device.byte_order = tomc_gateway_BYTE_ORDER_BIG;
  device.has_setpoint = !probe && controller != 0 && has_setpoint;
  device.setpoint_cycle = device.has_setpoint ? setpoint_cycle : 0;
  const uint16_t z = zsw1(), n = nist();
  actual_pzd[0] = (unsigned char)(z >> 8);
  actual_pzd[1] = (unsigned char)z;
  actual_pzd[2] = (unsigned char)(n >> 8);
  actual_pzd[3] = (unsigned char)n;
  device.slots[0].number = 1;
  device.slots[0].pzd._buffer = actual_pzd;
  device.slots[0].pzd._length = device.slots[0].pzd._maximum = 4;
  /* slots 1..3 unused: number 0, empty pzd (memset) */
  tomc_gateway_ActualCycle answer;
  memset(&answer, 0, sizeof answer);
  answer.contract_version = tomc_gateway_GATEWAY_CONTRACT_VERSION;
  snprintf(answer.gateway, sizeof answer.gateway, "%s", gateway_name);
  answer.incarnation = incarnation;
  answer.sequence_number = ++sequence;
  answer.controller = controller;
  answer.devices._buffer = &device;
  answer.devices._length = answer.devices._maximum = 1;
  if (dds_write(actual_writer, &answer) == DDS_RETCODE_OK) ++published;
}

static void publish_status(void) {
  tomc_gateway_DeviceDescription d;
  memset(&d, 0, sizeof d);
  snprintf(d.device, sizeof d.device, "%s", device_name);
  d.byte_order = tomc_gateway_BYTE_ORDER_BIG;
  d.telegrams[0] = 1;
  d.state = mismatch[0] != 0 ? tomc_gateway_DEVICE_CONFIG_MISMATCH : tomc_gateway_DEVICE_CONNECTED;
  snprintf(d.detail, sizeof d.detail, "%s", mismatch);
  tomc_gateway_GatewayStatus s;
  memset(&s, 0, sizeof s);
  s.contract_version = tomc_gateway_GATEWAY_CONTRACT_VERSION;
  snprintf(s.gateway, sizeof s.gateway, "%s", gateway_name);
  s.incarnation = incarnation;
  s.controller = owner;
  s.cycle_time_ns = (uint32_t)CYCLE_NS;
  s.setpoints_applied = applied;
  s.setpoint_gaps = gaps;
  s.setpoints_rejected = rejected;
  s.answers_published = published;
  s.devices._buffer = &d;
  s.devices._length = s.devices._maximum = 1;
  dds_write(status_writer, &s);
}

/* G3: exactly telegram 1 with 4 bytes in slot 0, big-endian, the other slots unused. */
static int entry_matches(const tomc_gateway_DeviceSetpoint* e) {
  if (e->byte_order != tomc_gateway_BYTE_ORDER_BIG) {
    snprintf(mismatch, sizeof mismatch, "the controller sends another byte order");
    return 0;
  }
  if (e->slots[0].number != 1 || e->slots[0].pzd._length != 4) {
    snprintf(mismatch, sizeof mismatch, "slot drive: telegram %u, configured 1",
             (unsigned)e->slots[0].number);
    return 0;
  }
  for (int k = 1; k < 4; ++k) {
    if (e->slots[k].number != 0 || e->slots[k].pzd._length != 0) {
      snprintf(mismatch, sizeof mismatch, "slot %d: telegram %u, configured none", k,
               (unsigned)e->slots[k].number);
      return 0;
    }
  }
  mismatch[0] = 0;
  return 1;
}

/* Returns 1 when the served controller or the status changed. */
static int on_setpoint(const tomc_gateway_SetpointCycle* s, int64_t now) {
  if (s->contract_version != tomc_gateway_GATEWAY_CONTRACT_VERSION || s->controller == 0 ||
      s->devices._length > tomc_gateway_MAX_DEVICES_PER_SAMPLE) {
    ++rejected;
    return 0;
  }
  const int served_elsewhere = owner != 0 && s->controller != owner && now - last_setpoint_ns < WATCHDOG_NS;
  if (s->devices._length == 0) { /* G9: a probe */
    if (served_elsewhere) {
      ++rejected;
    } else {
      publish_answer(s->controller, 1);
    }
    return 0;
  }
  if (served_elsewhere) {
    ++rejected;
    return 0;
  }
  int changed = 0;
  if (owner != s->controller) {
    owner = s->controller;
    have_cycle = 0;
    has_setpoint = 0;
    changed = 1;
  }
  if (have_cycle) {
    if (s->cycle <= last_cycle) {
      ++rejected;
      return changed;
    }
    gaps += s->cycle - last_cycle - 1;
  }
  have_cycle = 1;
  last_cycle = s->cycle;
  last_setpoint_ns = now;
  ++applied;
  const char old_mismatch = mismatch[0];
  for (uint32_t i = 0; i < s->devices._length; ++i) {
    const tomc_gateway_DeviceSetpoint* e = &s->devices._buffer[i];
    if (strcmp(e->device, device_name) != 0 || !entry_matches(e)) continue;
    const unsigned char* p = e->slots[0].pzd._buffer;
    stw1 = (uint16_t)((p[0] << 8) | p[1]);
    nsoll = (uint16_t)((p[2] << 8) | p[3]);
    has_setpoint = 1;
    setpoint_cycle = s->cycle;
  }
  drive_step();
  publish_answer(owner, 0);
  return changed || old_mismatch != mismatch[0];
}

int main(int argc, char** argv) {
  if (argc != 5 && !(argc == 6 && strcmp(argv[5], "xcdr2") == 0)) {
    fprintf(stderr, "usage: cyclone_gateway DOMAIN PARTITION DEVICE SECONDS [xcdr2]\n");
    return 2;
  }
  const dds_domainid_t domain = (dds_domainid_t)atoi(argv[1]);
  const char* partition = argv[2];
  device_name = argv[3];
  const int64_t end = now_ns() + (int64_t)(atof(argv[4]) * 1e9);
  srand((unsigned)now_ns());
  incarnation = random_id();
  signal(SIGTERM, on_signal);
  signal(SIGINT, on_signal);

  /* docs/gateway.md Appendix B, on loopback. */
  const char* config =
      "<CycloneDDS><Domain Id=\"any\">"
      "<General><Interfaces><NetworkInterface address=\"127.0.0.1\"/></Interfaces>"
      "<AllowMulticast>false</AllowMulticast></General>"
      "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
      "<MaxAutoParticipantIndex>31</MaxAutoParticipantIndex>"
      "<Peers><Peer address=\"127.0.0.1\"/></Peers></Discovery>"
      "</Domain></CycloneDDS>";
  const dds_entity_t dom = dds_create_domain(domain, config);
  if (dom < 0) {
    fprintf(stderr, "cyclone_gateway: dds_create_domain: %s\n", dds_strretcode(dom));
    return 1;
  }
  dds_qos_t* named = dds_create_qos();
  dds_qset_entity_name(named, gateway_name); /* what discovery shows the controller */
  const dds_entity_t participant = dds_create_participant(domain, named, NULL);
  dds_delete_qos(named);
  if (participant < 0) {
    fprintf(stderr, "cyclone_gateway: dds_create_participant: %s\n", dds_strretcode(participant));
    return 1;
  }
  dds_qos_t* pq = dds_create_qos();
  if (partition[0] != 0) dds_qset_partition1(pq, partition);
  const dds_entity_t publisher = dds_create_publisher(participant, pq, NULL);
  const dds_entity_t subscriber = dds_create_subscriber(participant, pq, NULL);
  dds_delete_qos(pq);

  const dds_data_representation_id_t xcdr1[] = {DDS_DATA_REPRESENTATION_XCDR1};
  const dds_data_representation_id_t xcdr2[] = {DDS_DATA_REPRESENTATION_XCDR2};
  const int break_representation = argc == 6;
  dds_qos_t* cyclic = dds_create_qos();
  dds_qset_reliability(cyclic, DDS_RELIABILITY_BEST_EFFORT, 0);
  dds_qset_durability(cyclic, DDS_DURABILITY_VOLATILE);
  dds_qset_data_representation(cyclic, 1, xcdr1);
  dds_qos_t* status_qos = dds_create_qos();
  dds_qset_reliability(status_qos, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
  dds_qset_durability(status_qos, DDS_DURABILITY_TRANSIENT_LOCAL);
  dds_qset_history(status_qos, DDS_HISTORY_KEEP_LAST, 1);
  dds_qset_data_representation(status_qos, 1, xcdr1);

  const dds_entity_t setpoint_topic =
      dds_create_topic(participant, &tomc_gateway_SetpointCycle_desc, "tomc/gateway/setpoint", NULL, NULL);
  const dds_entity_t actual_topic =
      dds_create_topic(participant, &tomc_gateway_ActualCycle_desc, "tomc/gateway/actual", NULL, NULL);
  const dds_entity_t status_topic =
      dds_create_topic(participant, &tomc_gateway_GatewayStatus_desc, "tomc/gateway/status", NULL, NULL);
  dds_qset_history(cyclic, DDS_HISTORY_KEEP_LAST, 4);
  const dds_entity_t reader = dds_create_reader(subscriber, setpoint_topic, cyclic, NULL);
  dds_qset_history(cyclic, DDS_HISTORY_KEEP_LAST, 1);
  if (break_representation) {
    dds_qset_data_representation(cyclic, 1, xcdr2);
    dds_qset_data_representation(status_qos, 1, xcdr2);
  }
  actual_writer = dds_create_writer(publisher, actual_topic, cyclic, NULL);
  status_writer = dds_create_writer(publisher, status_topic, status_qos, NULL);
  dds_delete_qos(cyclic);
  dds_delete_qos(status_qos);
  if (setpoint_topic < 0 || actual_topic < 0 || status_topic < 0 || reader < 0 || actual_writer < 0 ||
      status_writer < 0) {
    fprintf(stderr, "cyclone_gateway: could not create the topics, reader or writers\n");
    return 1;
  }
  const dds_entity_t waitset = dds_create_waitset(participant);
  const dds_entity_t readable = dds_create_readcondition(reader, DDS_ANY_STATE);
  dds_waitset_attach(waitset, readable, 0);

  printf("cyclone_gateway: '%s' serves %s on domain %d partition '%s'\n", gateway_name, device_name,
         (int)domain, partition);
  fflush(stdout);
  publish_status();
  int64_t status_at = now_ns(), idle_at = now_ns();
  while (!stop_requested && now_ns() < end) {
    dds_waitset_wait(waitset, NULL, 0, DDS_MSECS(1));
    void* samples[16] = {NULL};
    dds_sample_info_t infos[16];
    const dds_return_t n = dds_take(reader, samples, infos, 16, 16);
    const int64_t now = now_ns();
    int changed = 0;
    for (dds_return_t i = 0; i < n; ++i) {
      if (infos[i].valid_data) changed |= on_setpoint((const tomc_gateway_SetpointCycle*)samples[i], now);
    }
    if (n > 0) dds_return_loan(reader, samples, n);
    if (owner != 0 && now - last_setpoint_ns >= WATCHDOG_NS) { /* G6 */
      owner = 0;
      have_cycle = 0;
      has_setpoint = 0;
      stw1 = 0; /* the drive's setpoint is no longer presented as fresh: it coasts to S1 */
      drive_step();
      changed = 1;
    }
    if (owner == 0 && now - idle_at >= CYCLE_NS) { /* G7 */
      idle_at = now;
      publish_answer(0, 0);
    }
    if (changed || now - status_at >= STATUS_PERIOD_NS) { /* G8 */
      status_at = now;
      publish_status();
    }
  }
  printf("cyclone_gateway: %llu setpoints applied, %llu gaps, %llu rejected, %llu answers\n",
         (unsigned long long)applied, (unsigned long long)gaps, (unsigned long long)rejected,
         (unsigned long long)published);
  dds_delete(dom);
  return 0;
}
