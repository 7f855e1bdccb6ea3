#!/usr/bin/env python3
"""Writes crates/ais/fixtures/encounter.nmea: a small AIS log of a three-vessel encounter
in the English Channel, encoded with pyais (MIT; `pip install pyais`).

Ownship (MMSI 235000001, class A, !AIVDO) steams east at 12 kn; a class A
target (244000002) comes the other way at 10 kn 370 m north of ownship's
track (head-on); a class B yacht (338000003, types 18 and 24) crosses from the
north, heading south at 8 kn, from ownship's port side (crossing, ownship
stands on). A fourth vessel (211000004, class B extended, type 19) is 30 nm away,
outside the default import range. The log covers ten minutes up to
2024-05-01T12:00:00Z: position reports every 30 s (class A) or 60 s (class B),
static data (type 5 in two sentences, type 24 parts A and B), every line behind
an NMEA 4.0 tag block (`\\s:...,c:UNIXTIME*hh\\`), a base station report (an
unused type), a sentence with a wrong checksum and some lines that are not AIS.

    python3 scripts/make_ais_fixture.py > crates/ais/fixtures/encounter.nmea
"""
import math

from pyais.encode import encode_dict

T0 = 1714564800  # 2024-05-01T12:00:00Z, the time of the last line
A = 6378137.0
E2 = 6.69437999014e-3


def metres_per_degree(lat_deg):
    """(north, east) metres per degree of latitude and longitude on WGS84."""
    s = math.sin(math.radians(lat_deg))
    w = math.sqrt(1.0 - E2 * s * s)
    m = A * (1.0 - E2) / w**3
    n = A / w
    return m * math.pi / 180.0, n * math.cos(math.radians(lat_deg)) * math.pi / 180.0


def position(vessel, t):
    """(lat, lon) of a vessel sailing straight, at UNIX time t."""
    lat0, lon0 = vessel["at_t0"]
    run = vessel["speed"] * 1852.0 / 3600.0 * (t - T0)
    c = math.radians(vessel["course"])
    per_lat, per_lon = metres_per_degree(lat0)
    return lat0 + run * math.cos(c) / per_lat, lon0 + run * math.sin(c) / per_lon


def offset(origin, east_nm, north_nm):
    per_lat, per_lon = metres_per_degree(origin[0])
    return origin[0] + north_nm * 1852.0 / per_lat, origin[1] + east_nm * 1852.0 / per_lon


OWN_T0 = (50.30, -1.00)
VESSELS = {
    "own": dict(mmsi=235000001, at_t0=OWN_T0, course=90.0, speed=12.0, name="VORRT TRIAL",
                bow=80, stern=20, cls="A", talker="VDO", last=T0 - 4),
    "head_on": dict(mmsi=244000002, at_t0=offset(OWN_T0, 8.0, 0.2), course=270.0, speed=10.0,
                    name="NORTHSEA TRADER", bow=120, stern=30, cls="A", talker="VDM", last=T0 - 11),
    "crossing": dict(mmsi=338000003, at_t0=offset(OWN_T0, 4.0, 2.5), course=180.0, speed=8.0,
                     name="SEA BREEZE", bow=12, stern=3, cls="B", talker="VDM", last=T0 - 23),
    "far": dict(mmsi=211000004, at_t0=offset(OWN_T0, 0.0, 30.0), course=180.0, speed=9.0,
                name="FAR AWAY", bow=20, stern=5, cls="B19", talker="VDM", last=T0 - 40),
}


def checksum(body):
    value = 0
    for char in body:
        value ^= ord(char)
    return f"{value:02X}"


def tagged(t, sentence, extra=""):
    body = f"s:vorrt-fixture,c:{int(t)}{extra}"
    return f"\\{body}*{checksum(body)}\\{sentence}"


def encode(fields, talker):
    return encode_dict(fields, talker_id="AI", sentence_type=talker, radio_channel="A",
                       seq_id=fields.pop("_seq", None))


def position_fields(vessel, t, msg_type):
    lat, lon = position(vessel, t)
    fields = dict(type=msg_type, mmsi=vessel["mmsi"], lat=round(lat, 6), lon=round(lon, 6),
                  course=vessel["course"], speed=vessel["speed"], heading=int(vessel["course"]),
                  second=int(t) % 60)
    if msg_type == 19:
        fields.update(shipname=vessel["name"], to_bow=vessel["bow"], to_stern=vessel["stern"],
                      to_port=3, to_starboard=3)
    return fields


def main():
    lines = []  # (time, order, text)
    order = 0

    def add(t, text):
        nonlocal order
        order += 1
        lines.append((t, order, text))

    # Static data first.
    for key in ("own", "head_on"):
        v = VESSELS[key]
        parts = encode(dict(type=5, mmsi=v["mmsi"], shipname=v["name"], callsign="V" + key[:3].upper(),
                            to_bow=v["bow"], to_stern=v["stern"], to_port=8, to_starboard=8,
                            shiptype=70, destination="SOUTHAMPTON", _seq=1 if key == "own" else 2),
                       v["talker"])
        assert len(parts) == 2, "type 5 must take two sentences"
        t = T0 - 590 if key == "own" else T0 - 580
        add(t, tagged(t, parts[0], f",g:1-2-{10 + len(lines)}"))
        add(t, parts[1])  # second fragment without a tag block: time carried forward
    cross = VESSELS["crossing"]
    for part, t in ((0, T0 - 570), (1, T0 - 560)):
        fields = dict(type=24, mmsi=cross["mmsi"], partno=part)
        if part == 0:
            fields["shipname"] = cross["name"]
        else:
            fields.update(shiptype=37, callsign="YACHT1", to_bow=cross["bow"],
                          to_stern=cross["stern"], to_port=2, to_starboard=2)
        add(t, tagged(t, encode(fields, "VDM")[0]))

    # Position reports.
    for key, v in VESSELS.items():
        step = 30 if v["cls"] == "A" else 60
        t = v["last"] - 600 + 30
        kinds = [1, 2, 3] if key == "head_on" else [1]
        i = 0
        while t <= v["last"]:
            msg_type = {"A": kinds[i % len(kinds)], "B": 18, "B19": 19}[v["cls"]]
            for sentence in encode(position_fields(v, t, msg_type), v["talker"]):
                add(t, tagged(t, sentence))
            t += step
            i += 1

    # Noise: an unused type (4, base station), a bad checksum, garbage.
    base = encode(dict(type=4, mmsi=2320001, lat=50.5, lon=-1.3, year=2024, month=5, day=1,
                       hour=11, minute=55, second=0), "VDM")[0]
    add(T0 - 300, tagged(T0 - 300, base))
    good = encode(position_fields(VESSELS["own"], T0 - 2, 1), "VDO")[0]
    bad = good[:-2] + ("00" if good[-2:] != "00" else "11")
    add(T0 - 2, tagged(T0 - 2, bad))
    add(T0 - 200, "this line is not NMEA")
    add(T0 - 100, "$GPGGA,120000,5018.000,N,00100.000,W,1,08,0.9,10.0,M,47.0,M,,*47")
    add(T0 - 50, "!AIVDM,2,2,9,A,0000,2*00")  # a lone second fragment
    add(T0 - 30, "\\c:notatime*00\\!AIVDM,1,1,,A,000,0*00")
    # The last line: class B part A again, at T0.
    add(T0, tagged(T0, encode(dict(type=24, mmsi=cross["mmsi"], partno=0, shipname=cross["name"]),
                              "VDM")[0]))

    lines.sort()
    for _, _, text in lines:
        print(text)


if __name__ == "__main__":
    main()
