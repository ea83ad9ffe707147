// SPDX-License-Identifier: GPL-3.0-or-later
// Hosts the precompiled headers every test reuses (tests/CMakeLists.txt); it is never run.
int main() {
    return 0;
}
