<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en" sourcelanguage="en">
<context>
    <name>Acknowledge</name>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>not ready</source>
        <translation>not ready</translation>
    </message>
    <message>
        <source>address or password invalid</source>
        <translation>address or password invalid</translation>
    </message>
    <message>
        <source>data invalid</source>
        <translation>data invalid</translation>
    </message>
    <message>
        <source>parameter write protected</source>
        <translation>parameter write protected</translation>
    </message>
    <message>
        <source>BCC error</source>
        <translation>BCC error</translation>
    </message>
    <message>
        <source>inverter busy</source>
        <translation>inverter busy</translation>
    </message>
    <message>
        <source>service not available</source>
        <translation>service not available</translation>
    </message>
    <message>
        <source>password invalid</source>
        <translation>password invalid</translation>
    </message>
    <message>
        <source>telegram framing error: wrong count of characters</source>
        <translation>telegram framing error: wrong count of characters</translation>
    </message>
    <message>
        <source>transmission error: overrun, framing or parity error</source>
        <translation>transmission error: overrun, framing or parity error</translation>
    </message>
    <message>
        <source>set selection invalid</source>
        <translation>set selection invalid</translation>
    </message>
    <message>
        <source>language selection invalid</source>
        <translation>language selection invalid</translation>
    </message>
    <message>
        <source>address invalid</source>
        <translation>address invalid</translation>
    </message>
    <message>
        <source>operation not possible</source>
        <translation>operation not possible</translation>
    </message>
    <message>
        <source>unknown acknowledge 15</source>
        <translation>unknown acknowledge 15</translation>
    </message>
</context>
<context>
    <name>BackupCommit</name>
    <message>
        <source>%1: backup, %2 changed</source>
        <translation>%1: backup, %2 changed</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>cannot read %1: %2</translation>
    </message>
</context>
<context>
    <name>BackupRepository</name>
    <message>
        <source>cannot make the directory %1</source>
        <translation>cannot make the directory %1</translation>
    </message>
    <message>
        <source>the directory %1 does not exist</source>
        <translation>the directory %1 does not exist</translation>
    </message>
    <message>
        <source>%1 is not a git repository of backups: make it one with plant backup --commit</source>
        <translation>%1 is not a git repository of backups: make it one with plant backup --commit</translation>
    </message>
    <message>
        <source>there is no revision on or before %1 in %2</source>
        <translation>there is no revision on or before %1 in %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is no revision of %2: give a commit id, a tag or a date like 2026-11-24</source>
        <translation>&apos;%1&apos; is no revision of %2: give a commit id, a tag or a date like 2026-11-24</translation>
    </message>
    <message>
        <source>git cat-file: no object %1</source>
        <translation>git cat-file: no object %1</translation>
    </message>
    <message>
        <source>cannot make a temporary folder: %1</source>
        <translation>cannot make a temporary folder: %1</translation>
    </message>
</context>
<context>
    <name>ChosenValues</name>
    <message>
        <source>%1: the target has no such parameter</source>
        <translation>%1: the target has no such parameter</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>CliJournalText</name>
    <message>
        <source>no journal yet at %1: nothing was written</source>
        <translation>no journal yet at %1: nothing was written</translation>
    </message>
</context>
<context>
    <name>CliPlantHistory</name>
    <message>
        <source>no revision</source>
        <translation>no revision</translation>
    </message>
    <message>
        <source>no drive saved: nothing committed</source>
        <translation>no drive saved: nothing committed</translation>
    </message>
    <message>
        <source>no setting changed since the last commit: nothing committed</source>
        <translation>no setting changed since the last commit: nothing committed</translation>
    </message>
    <message>
        <source>committed %1: %2</source>
        <translation>committed %1: %2</translation>
    </message>
</context>
<context>
    <name>CliSpectrum</name>
    <message>
        <source>%1 in &apos;%2&apos;, %3 to %4 ms</source>
        <translation>%1 in &apos;%2&apos;, %3 to %4 ms</translation>
    </message>
    <message>
        <source>%1 samples at %2 Hz, %3 Hz a bin</source>
        <translation>%1 samples at %2 Hz, %3 Hz a bin</translation>
    </message>
    <message>
        <source>; they came unevenly and were resampled to even spacing</source>
        <translation>; they came unevenly and were resampled to even spacing</translation>
    </message>
    <message>
        <source>no peaks: the channel is flat in the window</source>
        <translation>no peaks: the channel is flat in the window</translation>
    </message>
    <message>
        <source>frequency [Hz]</source>
        <translation>frequency [Hz]</translation>
    </message>
    <message>
        <source>amplitude</source>
        <translation>amplitude</translation>
    </message>
    <message>
        <source>amplitude [%1]</source>
        <translation>amplitude [%1]</translation>
    </message>
    <message>
        <source>&apos;%1&apos; holds no samples</source>
        <translation>&apos;%1&apos; holds no samples</translation>
    </message>
    <message>
        <source>&apos;%1&apos; fits several channels of &apos;%2&apos;: give its title or number (%3)</source>
        <translation>&apos;%1&apos; fits several channels of &apos;%2&apos;: give its title or number (%3)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has no channel &apos;%2&apos;; it holds %3</source>
        <translation>&apos;%1&apos; has no channel &apos;%2&apos;; it holds %3</translation>
    </message>
    <message>
        <source>%1 %2 ms is outside the recording in &apos;%3&apos; (%4 to %5 ms)</source>
        <translation>%1 %2 ms is outside the recording in &apos;%3&apos; (%4 to %5 ms)</translation>
    </message>
</context>
<context>
    <name>ComparisonTable</name>
    <message>
        <source>equal</source>
        <translation>equal</translation>
    </message>
    <message>
        <source>different</source>
        <translation>different</translation>
    </message>
    <message>
        <source>only in A</source>
        <translation>only in A</translation>
    </message>
    <message>
        <source>only in B</source>
        <translation>only in B</translation>
    </message>
    <message>
        <source>read-only</source>
        <translation>read-only</translation>
    </message>
    <message>
        <source>not a setting</source>
        <translation>not a setting</translation>
    </message>
</context>
<context>
    <name>ConnectionOptions</name>
    <message>
        <source>--%1 %2: expected a number from %3 to %4</source>
        <translation>--%1 %2: expected a number from %3 to %4</translation>
    </message>
    <message>
        <source>unknown language &quot;%1&quot;: use en or de</source>
        <translation>unknown language &quot;%1&quot;: use en or de</translation>
    </message>
    <message>
        <source>--connect is missing: give tcp:HOST:PORT, serial:DEVICE or sim</source>
        <translation>--connect is missing: give tcp:HOST:PORT, serial:DEVICE or sim</translation>
    </message>
    <message>
        <source>unknown protocol &quot;%1&quot;: use hsp5, din66019ii or din66019</source>
        <translation>unknown protocol &quot;%1&quot;: use hsp5, din66019ii or din66019</translation>
    </message>
    <message>
        <source>--hsp5-extensions needs --protocol hsp5</source>
        <translation>--hsp5-extensions needs --protocol hsp5</translation>
    </message>
</context>
<context>
    <name>ConnectionSettingsText</name>
    <message>
        <source>&quot;%1&quot; is not HOST:PORT (an IPv6 address is written [ADDRESS]:PORT)</source>
        <translation>&quot;%1&quot; is not HOST:PORT (an IPv6 address is written [ADDRESS]:PORT)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has no port: write tcp:HOST:PORT</source>
        <translation>&quot;%1&quot; has no port: write tcp:HOST:PORT</translation>
    </message>
    <message>
        <source>the host is missing in &quot;%1&quot;: write tcp:HOST:PORT</source>
        <translation>the host is missing in &quot;%1&quot;: write tcp:HOST:PORT</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a TCP port (1..65535)</source>
        <translation>&quot;%1&quot; is not a TCP port (1..65535)</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: the simulated drive takes no further address (write sim)</source>
        <translation>&quot;%1&quot;: the simulated drive takes no further address (write sim)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; names no serial device: write serial:/dev/ttyUSB0 or serial:COM3</source>
        <translation>&quot;%1&quot; names no serial device: write serial:/dev/ttyUSB0 or serial:COM3</translation>
    </message>
    <message>
        <source>unknown connection &quot;%1&quot;: expected tcp:HOST:PORT, serial:DEVICE or sim</source>
        <translation>unknown connection &quot;%1&quot;: expected tcp:HOST:PORT, serial:DEVICE or sim</translation>
    </message>
    <message>
        <source>simulated %1 drive</source>
        <translation>simulated %1 drive</translation>
    </message>
    <message>
        <source>%1 on %2 (%3 %4)</source>
        <translation>%1 on %2 (%3 %4)</translation>
    </message>
    <message>
        <source>%1 via %2</source>
        <translation>%1 via %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a TCP port (0..65535, 0 picks a free one)</source>
        <translation>&quot;%1&quot; is not a TCP port (0..65535, 0 picks a free one)</translation>
    </message>
    <message>
        <source>%1 drive %2</source>
        <translation>%1 drive %2</translation>
    </message>
    <message>
        <source>auto</source>
        <translation>auto</translation>
    </message>
</context>
<context>
    <name>DisplayScaling</name>
    <message>
        <source>calculation mode %1</source>
        <translation>calculation mode %1</translation>
    </message>
    <message>
        <source>divisor 0</source>
        <translation>divisor 0</translation>
    </message>
    <message>
        <source>%1 (no scaling: %2)</source>
        <translation>%1 (no scaling: %2)</translation>
    </message>
    <message>
        <source>%1 (no scaling: value + offset is 0)</source>
        <translation>%1 (no scaling: value + offset is 0)</translation>
    </message>
    <message>
        <source>no value given</source>
        <translation>no value given</translation>
    </message>
    <message>
        <source>&apos;%1&apos; cannot be converted: the scaling of this parameter is invalid (%2)</source>
        <translation>&apos;%1&apos; cannot be converted: the scaling of this parameter is invalid (%2)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number</source>
        <translation>&apos;%1&apos; is not a number</translation>
    </message>
    <message>
        <source>unit &apos;%1&apos; does not match: this value has no unit</source>
        <translation>unit &apos;%1&apos; does not match: this value has no unit</translation>
    </message>
    <message>
        <source>unit &apos;%1&apos; does not match &apos;%2&apos;</source>
        <translation>unit &apos;%1&apos; does not match &apos;%2&apos;</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a hexadecimal number</source>
        <translation>&apos;%1&apos; is not a hexadecimal number</translation>
    </message>
    <message>
        <source>&apos;%1&apos; does not fit in 32 bits</source>
        <translation>&apos;%1&apos; does not fit in 32 bits</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has too many digits</source>
        <translation>&apos;%1&apos; has too many digits</translation>
    </message>
    <message>
        <source>every raw value shows 0 in this scaling (multiplier 0): the raw value cannot be chosen</source>
        <translation>every raw value shows 0 in this scaling (multiplier 0): the raw value cannot be chosen</translation>
    </message>
    <message>
        <source>no raw value gives %1 in this scaling</source>
        <translation>no raw value gives %1 in this scaling</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is out of range</source>
        <translation>&apos;%1&apos; is out of range</translation>
    </message>
    <message>
        <source>no raw value gives 0 in this scaling</source>
        <translation>no raw value gives 0 in this scaling</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is out of range: it needs raw value %2, beyond 32 bits</source>
        <translation>&apos;%1&apos; is out of range: it needs raw value %2, beyond 32 bits</translation>
    </message>
</context>
<context>
    <name>DownloadPlan</name>
    <message>
        <source>the file was made for &quot;%1&quot;, the drive is &quot;%2&quot;</source>
        <translation>the file was made for &quot;%1&quot;, the drive is &quot;%2&quot;</translation>
    </message>
    <message>
        <source>the drive&apos;s identification could not be read, so the file cannot be checked against it</source>
        <translation>the drive&apos;s identification could not be read, so the file cannot be checked against it</translation>
    </message>
    <message>
        <source>the file does not say which kind of drive it was made for (its identification parameters are missing)</source>
        <translation>the file does not say which kind of drive it was made for (its identification parameters are missing)</translation>
    </message>
    <message>
        <source>the file was made for another drive: %1 %2 is %3 in the file, %4 on the drive</source>
        <translation>the file was made for another drive: %1 %2 is %3 in the file, %4 on the drive</translation>
    </message>
    <message>
        <source>the file was made for another kind of drive</source>
        <translation>the file was made for another kind of drive</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) of the file are not on the drive: %1</source>
        <translation>
            <numerusform>%n parameter of the file is not on the drive: %1</numerusform>
            <numerusform>%n parameters of the file are not on the drive: %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) of the drive are not in the file: %1</source>
        <translation>
            <numerusform>%n parameter of the drive is not in the file: %1</numerusform>
            <numerusform>%n parameters of the drive are not in the file: %1</numerusform>
        </translation>
    </message>
    <message>
        <source>one value for all sets, left out by the sets chosen</source>
        <translation>one value for all sets, left out by the sets chosen</translation>
    </message>
    <message>
        <source>needs password level %1</source>
        <translation>needs password level %1</translation>
    </message>
    <message>
        <source>%1 not in the file (not read when it was made)</source>
        <translation>%1 not in the file (not read when it was made)</translation>
    </message>
    <message>
        <source>%1 (%2) %3 is outside %4 .. %5</source>
        <translation>%1 (%2) %3 is outside %4 .. %5</translation>
    </message>
    <message>
        <source>value</source>
        <translation>value</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) outside the drive&apos;s limits: %1</source>
        <translation>
            <numerusform>%n value outside the drive&apos;s limits: %1</numerusform>
            <numerusform>%n values outside the drive&apos;s limits: %1</numerusform>
        </translation>
    </message>
    <message>
        <source>not read</source>
        <translation>not read</translation>
    </message>
    <message>
        <source>%1  %2%3: %4 -&gt; %5%6
</source>
        <translation>%1  %2%3: %4 -&gt; %5%6
</translation>
    </message>
    <message>
        <source>  (always written)</source>
        <translation>  (always written)</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) to write</source>
        <translation>
            <numerusform>%n value to write</numerusform>
            <numerusform>%n values to write</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n unchanged</source>
        <translation>
            <numerusform>%n unchanged</numerusform>
            <numerusform>%n unchanged</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n left</source>
        <translation>
            <numerusform>%n left</numerusform>
            <numerusform>%n left</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n read-only value(s) differ and are never written</source>
        <translation>
            <numerusform>%n read-only value differs and is never written</numerusform>
            <numerusform>%n read-only values differ and are never written</numerusform>
        </translation>
    </message>
    <message>
        <source>group %1 %2</source>
        <translation>group %1 %2</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>%1 is in the file, not on the drive</source>
        <translation>%1 is in the file, not on the drive</translation>
    </message>
    <message>
        <source>%1 is on the drive, not in the file</source>
        <translation>%1 is on the drive, not in the file</translation>
    </message>
    <message>
        <source>%1: %2 is %3 in the file, %4 on the drive</source>
        <translation>%1: %2 is %3 in the file, %4 on the drive</translation>
    </message>
    <message>
        <source>the drive has no identification, and the file&apos;s metadata is not the drive&apos;s: %1</source>
        <translation>the drive has no identification, and the file&apos;s metadata is not the drive&apos;s: %1</translation>
    </message>
</context>
<context>
    <name>DownloadReport</name>
    <message>
        <source>the value</source>
        <translation>the value</translation>
    </message>
    <message>
        <source>not sent</source>
        <translation>not sent</translation>
    </message>
    <message>
        <source>not sent: %1</source>
        <translation>not sent: %1</translation>
    </message>
    <message>
        <source>%1 not sent: %2</source>
        <translation>%1 not sent: %2</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) written and read back</source>
        <translation>
            <numerusform>%n value written and read back</numerusform>
            <numerusform>%n values written and read back</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n unchanged</source>
        <translation>
            <numerusform>%n unchanged</numerusform>
            <numerusform>%n unchanged</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n refused</source>
        <translation>
            <numerusform>%n refused</numerusform>
            <numerusform>%n refused</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n skipped</source>
        <translation>
            <numerusform>%n skipped</numerusform>
            <numerusform>%n skipped</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n not written</source>
        <translation>
            <numerusform>%n not written</numerusform>
            <numerusform>%n not written</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n read-only value(s) of the file differ from the drive&apos;s; they are never written</source>
        <translation>
            <numerusform>%n read-only value of the file differs from the drive&apos;s; it is never written</numerusform>
            <numerusform>%n read-only values of the file differ from the drive&apos;s; they are never written</numerusform>
        </translation>
    </message>
    <message>
        <source>The download stopped: %1</source>
        <translation>The download stopped: %1</translation>
    </message>
    <message>
        <source>Written:</source>
        <translation>Written:</translation>
    </message>
    <message>
        <source>Refused:</source>
        <translation>Refused:</translation>
    </message>
    <message>
        <source>Skipped:</source>
        <translation>Skipped:</translation>
    </message>
    <message>
        <source>Not written:</source>
        <translation>Not written:</translation>
    </message>
    <message>
        <source>written %1, but %2 holds %3</source>
        <translation>written %1, but %2 holds %3</translation>
    </message>
    <message>
        <source>%1: no answer, so whether the drive took %2 is unknown (%3)</source>
        <translation>%1: no answer, so whether the drive took %2 is unknown (%3)</translation>
    </message>
    <message>
        <source>%1: the drive acknowledged %2, but it could not be read back (%3)</source>
        <translation>%1: the drive acknowledged %2, but it could not be read back (%3)</translation>
    </message>
    <message numerus="yes">
        <source>%n unknown</source>
        <translation>
            <numerusform>%n unknown</numerusform>
            <numerusform>%n unknown</numerusform>
        </translation>
    </message>
    <message>
        <source>Unknown (sent, no answer):</source>
        <translation>Unknown (sent, no answer):</translation>
    </message>
    <message>
        <source>%1: no answer to writing %2, and the drive holds %3: not written</source>
        <translation>%1: no answer to writing %2, and the drive holds %3: not written</translation>
    </message>
</context>
<context>
    <name>DriveChange</name>
    <message>
        <source>%1 %2: no longer on the drive (was %3)</source>
        <translation>%1 %2: no longer on the drive (was %3)</translation>
    </message>
    <message>
        <source>%1 %2: new on the drive, %3</source>
        <translation>%1 %2: new on the drive, %3</translation>
    </message>
    <message>
        <source>%1 %2: %3 -&gt; %4</source>
        <translation>%1 %2: %3 -&gt; %4</translation>
    </message>
    <message>
        <source>%1 %2 set %3: %4 -&gt; %5</source>
        <translation>%1 %2 set %3: %4 -&gt; %5</translation>
    </message>
    <message>
        <source>%1 added</source>
        <translation>%1 added</translation>
    </message>
    <message>
        <source>%1 gone</source>
        <translation>%1 gone</translation>
    </message>
    <message>
        <source>%1: the file cannot be read: %2</source>
        <translation>%1: the file cannot be read: %2</translation>
    </message>
</context>
<context>
    <name>DriveDesk</name>
    <message>
        <source>offline records of %1, one a millisecond assumed</source>
        <translation>offline records of %1, one a millisecond assumed</translation>
    </message>
</context>
<context>
    <name>DriveDesk::AccessController</name>
    <message>
        <source>The password level could not be read: %1</source>
        <translation>The password level could not be read: %1</translation>
    </message>
    <message>
        <source>Password not accepted: %1</source>
        <translation>Password not accepted: %1</translation>
    </message>
    <message>
        <source>Password accepted</source>
        <translation>Password accepted</translation>
    </message>
    <message>
        <source>The password parameter reads %1, which names no password level: the level stays %2</source>
        <translation>The password parameter reads %1, which names no password level: the level stays %2</translation>
    </message>
    <message>
        <source>Password level: %1</source>
        <translation>Password level: %1</translation>
    </message>
    <message>
        <source>the connection closed before the drive answered</source>
        <translation>the connection closed before the drive answered</translation>
    </message>
</context>
<context>
    <name>DriveDesk::AccessFeature</name>
    <message>
        <source>&amp;Password...</source>
        <translation>&amp;Password...</translation>
    </message>
    <message>
        <source>Enter a password to open a higher password level</source>
        <translation>Enter a password to open a higher password level</translation>
    </message>
    <message>
        <source>The password level in force on the drive (ud.01)</source>
        <translation>The password level in force on the drive (ud.01)</translation>
    </message>
    <message>
        <source>Password level: %1</source>
        <translation>Password level: %1</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>not connected</translation>
    </message>
</context>
<context>
    <name>DriveDesk::BaudRateSearch</name>
    <message>
        <source>%1: no drive answered at %2 Bd</source>
        <translation>%1: no drive answered at %2 Bd</translation>
    </message>
    <message>
        <source>%1: this program cannot open such a connection</source>
        <translation>%1: this program cannot open such a connection</translation>
    </message>
    <message>
        <source>looking for the drive at %1 Bd</source>
        <translation>looking for the drive at %1 Bd</translation>
    </message>
</context>
<context>
    <name>DriveDesk::BitFieldEditor</name>
    <message>
        <source>Definition %1</source>
        <translation>Definition %1</translation>
    </message>
    <message>
        <source>%1 (no plaintext)</source>
        <translation>%1 (no plaintext)</translation>
    </message>
    <message>
        <source>%1:</source>
        <translation>%1:</translation>
    </message>
    <message>
        <source>Value: %1</source>
        <translation>Value: %1</translation>
    </message>
</context>
<context>
    <name>DriveDesk::CliPlant</name>
    <message>
        <source>cannot make the directory %1</source>
        <translation>cannot make the directory %1</translation>
    </message>
    <message>
        <source>the directory %1 does not exist</source>
        <translation>the directory %1 does not exist</translation>
    </message>
    <message>
        <source>stopping every link after the value on its way...</source>
        <translation>stopping every link after the value on its way...</translation>
    </message>
    <message>
        <source>reading</source>
        <translation>reading</translation>
    </message>
    <message>
        <source>%1: the addresses found written</source>
        <translation>%1: the addresses found written</translation>
    </message>
    <message>
        <source>no link answered</source>
        <translation>no link answered</translation>
    </message>
    <message>
        <source>gave no identification</source>
        <translation>gave no identification</translation>
    </message>
    <message numerus="yes">
        <source>%1: saved %2, %n parameter(s)</source>
        <translation>
            <numerusform>%1: saved %2, %n parameter</numerusform>
            <numerusform>%1: saved %2, %n parameters</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: not saved: %2: %3</source>
        <translation>%1: not saved: %2: %3</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n difference(s)</source>
        <translation>
            <numerusform>%1: %n difference</numerusform>
            <numerusform>%1: %n differences</numerusform>
        </translation>
    </message>
    <message>
        <source>set %1</source>
        <translation>set %1</translation>
    </message>
    <message>
        <source>file %1  drive %2</source>
        <translation>file %1  drive %2</translation>
    </message>
    <message>
        <source>only in the file</source>
        <translation>only in the file</translation>
    </message>
    <message>
        <source>only on the drive</source>
        <translation>only on the drive</translation>
    </message>
    <message>
        <source>checked, nothing written</source>
        <translation>checked, nothing written</translation>
    </message>
    <message>
        <source>downloaded or already equal</source>
        <translation>downloaded or already equal</translation>
    </message>
    <message>
        <source>nothing was written: %1 (--no-journal downloads without it)</source>
        <translation>nothing was written: %1 (--no-journal downloads without it)</translation>
    </message>
    <message>
        <source>plant download of %1</source>
        <translation>plant download of %1</translation>
    </message>
    <message>
        <source>--no-journal downloads without it</source>
        <translation>--no-journal downloads without it</translation>
    </message>
</context>
<context>
    <name>DriveDesk::CliRunner</name>
    <message>
        <source>cannot connect to %1: %2</source>
        <translation>cannot connect to %1: %2</translation>
    </message>
    <message>
        <source>%1 (DIN66019 has no group names: give the address, e.g. 0x0203)</source>
        <translation>%1 (DIN66019 has no group names: give the address, e.g. 0x0203)</translation>
    </message>
    <message>
        <source>%1 = %2 (raw)</source>
        <translation>%1 = %2 (raw)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a raw 16-bit value (DIN66019 writes raw values)</source>
        <translation>&apos;%1&apos; is not a raw 16-bit value (DIN66019 writes raw values)</translation>
    </message>
    <message>
        <source>metadata from the cache of this kind of drive (%1); --no-cache reads it from the drive</source>
        <translation>metadata from the cache of this kind of drive (%1); --no-cache reads it from the drive</translation>
    </message>
    <message>
        <source>could not read the groups: %1</source>
        <translation>could not read the groups: %1</translation>
    </message>
    <message>
        <source>scan incomplete: %1</source>
        <translation>scan incomplete: %1</translation>
    </message>
    <message>
        <source>the drive has no parameter %1</source>
        <translation>the drive has no parameter %1</translation>
    </message>
    <message>
        <source>set %1</source>
        <translation>set %1</translation>
    </message>
    <message>
        <source>active set</source>
        <translation>active set</translation>
    </message>
    <message>
        <source>%1  %2 = %3  (raw %4, %5)</source>
        <translation>%1  %2 = %3  (raw %4, %5)</translation>
    </message>
    <message>
        <source>%1: %2; nothing was written</source>
        <translation>%1: %2; nothing was written</translation>
    </message>
    <message>
        <source>password not accepted: %1</source>
        <translation>password not accepted: %1</translation>
    </message>
    <message>
        <source>password level in force: %1</source>
        <translation>password level in force: %1</translation>
    </message>
    <message>
        <source>could not read the drive: %1</source>
        <translation>could not read the drive: %1</translation>
    </message>
    <message>
        <source>DIN66019 carries parameter values only; use --protocol din66019ii for anything but read and write</source>
        <translation>DIN66019 carries parameter values only; use --protocol din66019ii for anything but read and write</translation>
    </message>
    <message>
        <source>stopping after the value on its way...</source>
        <translation>stopping after the value on its way...</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n parameter(s)</source>
        <translation>
            <numerusform>%1: %n parameter</numerusform>
            <numerusform>%1: %n parameters</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n value(s)</source>
        <translation>
            <numerusform>%n value</numerusform>
            <numerusform>%n values</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n write-only with the default</source>
        <translation>
            <numerusform>%n write-only with the default</numerusform>
            <numerusform>%n write-only with the default</numerusform>
        </translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>warning: %1</translation>
    </message>
    <message>
        <source>refused: %1</source>
        <translation>refused: %1</translation>
    </message>
    <message>
        <source>nothing was written; --force writes the file all the same</source>
        <translation>nothing was written; --force writes the file all the same</translation>
    </message>
    <message>
        <source>skipped  %1  %2: %3</source>
        <translation>skipped  %1  %2: %3</translation>
    </message>
    <message>
        <source>the download did not write everything; the report says what the drive holds</source>
        <translation>the download did not write everything; the report says what the drive holds</translation>
    </message>
    <message>
        <source>dry run: %1; nothing was written</source>
        <translation>dry run: %1; nothing was written</translation>
    </message>
    <message>
        <source>the drive could not be read: %1</source>
        <translation>the drive could not be read: %1</translation>
    </message>
    <message>
        <source>the channels could not be assigned: %1</source>
        <translation>the channels could not be assigned: %1</translation>
    </message>
    <message>
        <source>every scope channel of the drive is off: choose what to record with --channels, e.g. --channels ru.3,ru.9</source>
        <translation>every scope channel of the drive is off: choose what to record with --channels, e.g. --channels ru.3,ru.9</translation>
    </message>
    <message>
        <source>recording: %1 s, %2 Hz, %3 lost, %4 failed</source>
        <translation>recording: %1 s, %2 Hz, %3 lost, %4 failed</translation>
    </message>
    <message>
        <source>recording %1 for %2 s; Ctrl+C stops and writes what was recorded</source>
        <translation>recording %1 for %2 s; Ctrl+C stops and writes what was recorded</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n sample(s) over %2 s, achieved %3 Hz</source>
        <translation>
            <numerusform>%1: %n sample over %2 s, achieved %3 Hz</numerusform>
            <numerusform>%1: %n samples over %2 s, achieved %3 Hz</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 lost, %2 failed</source>
        <translation>%1 lost, %2 failed</translation>
    </message>
    <message>
        <source>the recording ended early: %1</source>
        <translation>the recording ended early: %1</translation>
    </message>
    <message>
        <source>reading offline record %1 of %2</source>
        <translation>reading offline record %1 of %2</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n offline record(s), one a millisecond assumed</source>
        <translation>
            <numerusform>%1: %n offline record, one a millisecond assumed</numerusform>
            <numerusform>%1: %n offline records, one a millisecond assumed</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>warning: %n record(s) had channel 3 or 4 beyond 16 bits and hold the nearest 16-bit value</source>
        <translation>
            <numerusform>warning: %n record had channel 3 or 4 beyond 16 bits and holds the nearest 16-bit value</numerusform>
            <numerusform>warning: %n records had channel 3 or 4 beyond 16 bits and hold the nearest 16-bit value</numerusform>
        </translation>
    </message>
    <message>
        <source>the records could not all be read: %1</source>
        <translation>the records could not all be read: %1</translation>
    </message>
    <message>
        <source>found the drive at %1 Bd</source>
        <translation>found the drive at %1 Bd</translation>
    </message>
    <message>
        <source>scan</source>
        <translation>scan</translation>
    </message>
    <message numerus="yes">
        <source>%1 stopped after %2 of %n parameter(s)</source>
        <translation>
            <numerusform>%1 stopped after %2 of %n parameter</numerusform>
            <numerusform>%1 stopped after %2 of %n parameters</numerusform>
        </translation>
    </message>
    <message>
        <source>no answer</source>
        <translation>no answer</translation>
    </message>
    <message>
        <source>the drive stopped answering (%1): %2</source>
        <translation>the drive stopped answering (%1): %2</translation>
    </message>
    <message>
        <source>not read: %1</source>
        <translation>not read: %1</translation>
    </message>
    <message>
        <source>the connection to the drive was closed</source>
        <translation>the connection to the drive was closed</translation>
    </message>
    <message>
        <source>the connection to the drive was lost (%1): %2</source>
        <translation>the connection to the drive was lost (%1): %2</translation>
    </message>
    <message>
        <source>%1; nothing was written</source>
        <translation>%1; nothing was written</translation>
    </message>
    <message>
        <source>%1 not written: %2 (--no-journal writes without it)</source>
        <translation>%1 not written: %2 (--no-journal writes without it)</translation>
    </message>
    <message>
        <source>write %1</source>
        <translation>write %1</translation>
    </message>
    <message>
        <source>no journal yet at %1: there is nothing to revert</source>
        <translation>no journal yet at %1: there is nothing to revert</translation>
    </message>
    <message>
        <source>left out: %1</source>
        <translation>left out: %1</translation>
    </message>
    <message>
        <source>nothing was written</source>
        <translation>nothing was written</translation>
    </message>
    <message>
        <source>no entry of this drive to revert; nothing was written</source>
        <translation>no entry of this drive to revert; nothing was written</translation>
    </message>
    <message>
        <source>%1: the values before, back to the drive</source>
        <translation>%1: the values before, back to the drive</translation>
    </message>
    <message>
        <source>nothing was written: %1 (--no-journal downloads without it)</source>
        <translation>nothing was written: %1 (--no-journal downloads without it)</translation>
    </message>
    <message>
        <source>download of %1</source>
        <translation>download of %1</translation>
    </message>
    <message>
        <source>--no-journal downloads without it</source>
        <translation>--no-journal downloads without it</translation>
    </message>
    <message>
        <source>scope channel assignment</source>
        <translation>scope channel assignment</translation>
    </message>
    <message>
        <source>--no-journal writes without it</source>
        <translation>--no-journal writes without it</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ClientWorker</name>
    <message>
        <source>arrived before the open request was sent, ignored: %1</source>
        <translation>arrived before the open request was sent, ignored: %1</translation>
    </message>
    <message>
        <source>a request where answers are expected, ignored: %1</source>
        <translation>a request where answers are expected, ignored: %1</translation>
    </message>
    <message>
        <source>the answer with invoke id %1 belongs to no open request, ignored</source>
        <translation>the answer with invoke id %1 belongs to no open request, ignored</translation>
    </message>
    <message>
        <source>the answer does not match its request (%1), not accepted</source>
        <translation>the answer does not match its request (%1), not accepted</translation>
    </message>
    <message>
        <source>line error: %1</source>
        <translation>line error: %1</translation>
    </message>
    <message>
        <source>inverter request: %1</source>
        <translation>inverter request: %1</translation>
    </message>
    <message>
        <source>cannot answer the inverter&apos;s request: %1</source>
        <translation>cannot answer the inverter&apos;s request: %1</translation>
    </message>
    <message>
        <source>the client was closed</source>
        <translation>the client was closed</translation>
    </message>
    <message>
        <source>disconnected</source>
        <translation>disconnected</translation>
    </message>
    <message>
        <source>the link was lost</source>
        <translation>the link was lost</translation>
    </message>
    <message>
        <source>only requests can be sent, this is an answer</source>
        <translation>only requests can be sent, this is an answer</translation>
    </message>
    <message>
        <source>%1 has no %2 of %3</source>
        <translation>%1 has no %2 of %3</translation>
    </message>
    <message>
        <source>write</source>
        <translation>write</translation>
    </message>
    <message>
        <source>read</source>
        <translation>read</translation>
    </message>
    <message>
        <source>drive address %1 is outside 0..239 (240..255: groups and broadcast)</source>
        <translation>drive address %1 is outside 0..239 (240..255: groups and broadcast)</translation>
    </message>
    <message>
        <source>address %1 is a group or broadcast address: no drive answers there, so it takes writes only</source>
        <translation>address %1 is a group or broadcast address: no drive answers there, so it takes writes only</translation>
    </message>
    <message>
        <source>the codec cannot encode it</source>
        <translation>the codec cannot encode it</translation>
    </message>
    <message>
        <source>to drive %1: %2</source>
        <translation>to drive %1: %2</translation>
    </message>
    <message numerus="yes">
        <source>no request in flight was answered: one request at a time, each after %n ms of quiet line, until the drive answers again</source>
        <translation>
            <numerusform>no request in flight was answered: one request at a time, each after %n ms of quiet line, until the drive answers again</numerusform>
            <numerusform>no request in flight was answered: one request at a time, each after %n ms of quiet line, until the drive answers again</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: this program cannot open such a connection</source>
        <translation>%1: this program cannot open such a connection</translation>
    </message>
    <message numerus="yes">
        <source>%n timeout(s)</source>
        <translation>
            <numerusform>%n timeout</numerusform>
            <numerusform>%n timeouts</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n answer(s) with a wrong BCC</source>
        <translation>
            <numerusform>%n answer with a wrong BCC</numerusform>
            <numerusform>%n answers with a wrong BCC</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n line error(s)</source>
        <translation>
            <numerusform>%n line error</numerusform>
            <numerusform>%n line errors</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n unreadable answer(s)</source>
        <translation>
            <numerusform>%n unreadable answer</numerusform>
            <numerusform>%n unreadable answers</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n answer(s) that did not match the request</source>
        <translation>
            <numerusform>%n answer that did not match the request</numerusform>
            <numerusform>%n answers that did not match the request</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n transient refusal(s) (%1)</source>
        <translation>
            <numerusform>%n transient refusal (%1)</numerusform>
            <numerusform>%n transient refusals (%1)</numerusform>
        </translation>
    </message>
    <message>
        <source>timeout %1 ms</source>
        <translation>timeout %1 ms</translation>
    </message>
    <message>
        <source>no answer within %1 ms (attempt %2 of %3), asking again</source>
        <translation>no answer within %1 ms (attempt %2 of %3), asking again</translation>
    </message>
    <message>
        <source>no answer within %1 ms (attempt %2 of %3), given up</source>
        <translation>no answer within %1 ms (attempt %2 of %3), given up</translation>
    </message>
    <message>
        <source>the drive answers again: requests are sent as before</source>
        <translation>the drive answers again: requests are sent as before</translation>
    </message>
    <message numerus="yes">
        <source>no answer to %n request(s) in %1 s</source>
        <translation>
            <numerusform>no answer to %n request in %1 s</numerusform>
            <numerusform>no answer to %n requests in %1 s</numerusform>
        </translation>
    </message>
    <message>
        <source>the drive stopped answering (%1): the requests queued fail, and one request at a time is sent once until the drive answers again</source>
        <translation>the drive stopped answering (%1): the requests queued fail, and one request at a time is sent once until the drive answers again</translation>
    </message>
    <message numerus="yes">
        <source>%n request(s) in a row answered only with answers to an earlier request</source>
        <translation>
            <numerusform>%n request in a row answered only with answers to an earlier request</numerusform>
            <numerusform>%n requests in a row answered only with answers to an earlier request</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n request(s) in a row answered only with frames of the wrong length</source>
        <translation>
            <numerusform>%n request in a row answered only with frames of the wrong length</numerusform>
            <numerusform>%n requests in a row answered only with frames of the wrong length</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n request(s) in a row answered only with frames with a wrong checksum</source>
        <translation>
            <numerusform>%n request in a row answered only with frames with a wrong checksum</numerusform>
            <numerusform>%n requests in a row answered only with frames with a wrong checksum</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n request(s) in a row answered only with answers to no request sent</source>
        <translation>
            <numerusform>%n request in a row answered only with answers to no request sent</numerusform>
            <numerusform>%n requests in a row answered only with answers to no request sent</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n request(s) in a row answered only with characters the line flagged as broken</source>
        <translation>
            <numerusform>%n request in a row answered only with characters the line flagged as broken</numerusform>
            <numerusform>%n requests in a row answered only with characters the line flagged as broken</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n request(s) in a row answered only with bytes that never made a telegram</source>
        <translation>
            <numerusform>%n request in a row answered only with bytes that never made a telegram</numerusform>
            <numerusform>%n requests in a row answered only with bytes that never made a telegram</numerusform>
        </translation>
    </message>
    <message>
        <source>the drive has gone silent: a request was given up after every attempt and no valid answer came from the drive since</source>
        <translation>the drive has gone silent: a request was given up after every attempt and no valid answer came from the drive since</translation>
    </message>
</context>
<context>
    <name>DriveDesk::CompareFeature</name>
    <message>
        <source>Co&amp;mpare...</source>
        <translation>Co&amp;mpare...</translation>
    </message>
    <message>
        <source>Compare the drive, parameter files and defaults, and write chosen values</source>
        <translation>Compare the drive, parameter files and defaults, and write chosen values</translation>
    </message>
    <message numerus="yes">
        <source>Write %n compared value(s)</source>
        <translation>
            <numerusform>Write %n compared value</numerusform>
            <numerusform>Write %n compared values</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>DriveDesk::CompareWindow</name>
    <message>
        <source>Compare Parameters - DriveDesk</source>
        <translation>Compare Parameters - DriveDesk</translation>
    </message>
    <message>
        <source>Compare one &amp;set of A with one set of B</source>
        <translation>Compare one &amp;set of A with one set of B</translation>
    </message>
    <message>
        <source>Only the set-programmable parameters, in the sets chosen on each side. Choose &quot;A itself&quot; for B to compare two sets of one drive or file.</source>
        <translation>Only the set-programmable parameters, in the sets chosen on each side. Choose &quot;A itself&quot; for B to compare two sets of one drive or file.</translation>
    </message>
    <message>
        <source>&amp;Compare</source>
        <translation>&amp;Compare</translation>
    </message>
    <message>
        <source>C&amp;hoose Shown</source>
        <translation>C&amp;hoose Shown</translation>
    </message>
    <message>
        <source>Tick every row shown whose value can be written</source>
        <translation>Tick every row shown whose value can be written</translation>
    </message>
    <message>
        <source>C&amp;lear Choice</source>
        <translation>C&amp;lear Choice</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Close</translation>
    </message>
    <message>
        <source>Side &amp;A:</source>
        <translation>Side &amp;A:</translation>
    </message>
    <message>
        <source>Side &amp;B:</source>
        <translation>Side &amp;B:</translation>
    </message>
    <message>
        <source>The drive</source>
        <translation>The drive</translation>
    </message>
    <message>
        <source>The file shown in the window</source>
        <translation>The file shown in the window</translation>
    </message>
    <message>
        <source>A file</source>
        <translation>A file</translation>
    </message>
    <message>
        <source>Defaults of A</source>
        <translation>Defaults of A</translation>
    </message>
    <message>
        <source>A itself (another set)</source>
        <translation>A itself (another set)</translation>
    </message>
    <message>
        <source>Parameter file (*.json)</source>
        <translation>Parameter file (*.json)</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Browse...</translation>
    </message>
    <message>
        <source>Set:</source>
        <translation>Set:</translation>
    </message>
    <message>
        <source>Show:</source>
        <translation>Show:</translation>
    </message>
    <message>
        <source>All groups</source>
        <translation>All groups</translation>
    </message>
    <message>
        <source>&amp;Group:</source>
        <translation>&amp;Group:</translation>
    </message>
    <message>
        <source>Search id, name or value</source>
        <translation>Search id, name or value</translation>
    </message>
    <message>
        <source>Sea&amp;rch:</source>
        <translation>Sea&amp;rch:</translation>
    </message>
    <message>
        <source>Show only the rows ticked to be written: a last look</source>
        <translation>Show only the rows ticked to be written: a last look</translation>
    </message>
    <message>
        <source>Ra&amp;w values</source>
        <translation>Ra&amp;w values</translation>
    </message>
    <message>
        <source>Side A: Parameter File</source>
        <translation>Side A: Parameter File</translation>
    </message>
    <message>
        <source>Side B: Parameter File</source>
        <translation>Side B: Parameter File</translation>
    </message>
    <message>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <source>B</source>
        <translation>B</translation>
    </message>
    <message>
        <source>Side %1: no drive is connected and read.</source>
        <translation>Side %1: no drive is connected and read.</translation>
    </message>
    <message>
        <source>the drive</source>
        <translation>the drive</translation>
    </message>
    <message>
        <source>Side %1: the window shows no parameter file.</source>
        <translation>Side %1: the window shows no parameter file.</translation>
    </message>
    <message>
        <source>%1 (shown)</source>
        <translation>%1 (shown)</translation>
    </message>
    <message>
        <source>Side %1: choose a parameter file.</source>
        <translation>Side %1: choose a parameter file.</translation>
    </message>
    <message>
        <source>defaults of %1</source>
        <translation>defaults of %1</translation>
    </message>
    <message>
        <source>%1, set %2</source>
        <translation>%1, set %2</translation>
    </message>
    <message numerus="yes">
        <source>Compared %1 with %2: %n value(s) differ.</source>
        <translation>
            <numerusform>Compared %1 with %2: %n value differs.</numerusform>
            <numerusform>Compared %1 with %2: %n values differ.</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Equal (%1)</source>
        <translation>&amp;Equal (%1)</translation>
    </message>
    <message>
        <source>&amp;Different (%1)</source>
        <translation>&amp;Different (%1)</translation>
    </message>
    <message>
        <source>Only in A (%1)</source>
        <translation>Only in A (%1)</translation>
    </message>
    <message>
        <source>Only in B (%1)</source>
        <translation>Only in B (%1)</translation>
    </message>
    <message>
        <source>Read-&amp;only (%1)</source>
        <translation>Read-&amp;only (%1)</translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n value(s) shown, %2 chosen.</source>
        <translation>
            <numerusform>%1 of %n value shown, %2 chosen.</numerusform>
            <numerusform>%1 of %n values shown, %2 chosen.</numerusform>
        </translation>
    </message>
    <message>
        <source>Write to A</source>
        <translation>Write to A</translation>
    </message>
    <message>
        <source>Write to B</source>
        <translation>Write to B</translation>
    </message>
    <message numerus="yes">
        <source>Write %n Value(s) to A (%1)</source>
        <translation>
            <numerusform>Write %n Value to A (%1)</numerusform>
            <numerusform>Write %n Values to A (%1)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Write %n Value(s) to B (%1)</source>
        <translation>
            <numerusform>Write %n Value to B (%1)</numerusform>
            <numerusform>Write %n Values to B (%1)</numerusform>
        </translation>
    </message>
    <message>
        <source>Compare Parameters</source>
        <translation>Compare Parameters</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) were not written:</source>
        <translation>
            <numerusform>%n value was not written:</numerusform>
            <numerusform>%n values were not written:</numerusform>
        </translation>
    </message>
    <message>
        <source>Nothing written: no drive is connected that takes a download.</source>
        <translation>Nothing written: no drive is connected that takes a download.</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) handed to the window&apos;s download to the drive; it shows what it writes before it does.</source>
        <translation>
            <numerusform>%n value handed to the window&apos;s download to the drive; it shows what it writes before it does.</numerusform>
            <numerusform>%n values handed to the window&apos;s download to the drive; it shows what it writes before it does.</numerusform>
        </translation>
    </message>
    <message>
        <source>Nothing written: the window no longer shows %1.</source>
        <translation>Nothing written: the window no longer shows %1.</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) changed in %1 as one undoable edit of the window; save the file there to keep them.</source>
        <translation>
            <numerusform>%n value changed in %1 as one undoable edit of the window; save the file there to keep it.</numerusform>
            <numerusform>%n values changed in %1 as one undoable edit of the window; save the file there to keep them.</numerusform>
        </translation>
    </message>
    <message>
        <source>Could not save %1: %2. The file on disk is as it was.</source>
        <translation>Could not save %1: %2. The file on disk is as it was.</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) written into %1.</source>
        <translation>
            <numerusform>%n value written into %1.</numerusform>
            <numerusform>%n values written into %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>Live and read-only values and parameters a parameter list leaves out: never counted as a difference</source>
        <translation>Live and read-only values and parameters a parameter list leaves out: never counted as a difference</translation>
    </message>
    <message>
        <source>&amp;Not settings (%1)</source>
        <translation>&amp;Not settings (%1)</translation>
    </message>
    <message>
        <source>Chosen onl&amp;y</source>
        <translation>Chosen onl&amp;y</translation>
    </message>
    <message>
        <source>Side %1: could not read the file: %2</source>
        <translation>Side %1: could not read the file: %2</translation>
    </message>
    <message>
        <source>Nothing written: could not read the file: %1</source>
        <translation>Nothing written: could not read the file: %1</translation>
    </message>
    <message>
        <source>A drive read for this comparison is not written to here: open the drive in the editor to change it.</source>
        <translation>A drive read for this comparison is not written to here: open the drive in the editor to change it.</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ComparisonModel</name>
    <message>
        <source>%1 - %2</source>
        <translation>%1 - %2</translation>
    </message>
    <message>
        <source>?</source>
        <translation>?</translation>
    </message>
    <message>
        <source>all</source>
        <translation>all</translation>
    </message>
    <message>
        <source>%1 / %2</source>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <source>read-only, different</source>
        <translation>read-only, different</translation>
    </message>
    <message>
        <source>read-only, equal</source>
        <translation>read-only, equal</translation>
    </message>
    <message>
        <source>The parameter holds one value for every set.</source>
        <translation>The parameter holds one value for every set.</translation>
    </message>
    <message>
        <source>A download does not write this parameter: neither side can be changed to the other&apos;s value here.</source>
        <translation>A download does not write this parameter: neither side can be changed to the other&apos;s value here.</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Set</source>
        <translation>Set</translation>
    </message>
    <message>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <source>A: %1</source>
        <translation>A: %1</translation>
    </message>
    <message>
        <source>B</source>
        <translation>B</translation>
    </message>
    <message>
        <source>B: %1</source>
        <translation>B: %1</translation>
    </message>
    <message>
        <source>State</source>
        <translation>State</translation>
    </message>
    <message>
        <source>not a setting, only in A</source>
        <translation>not a setting, only in A</translation>
    </message>
    <message>
        <source>not a setting, only in B</source>
        <translation>not a setting, only in B</translation>
    </message>
    <message>
        <source>not a setting, different</source>
        <translation>not a setting, different</translation>
    </message>
    <message>
        <source>not a setting, equal</source>
        <translation>not a setting, equal</translation>
    </message>
    <message>
        <source>A live or read-only value, or one a parameter list leaves out: shown, never counted as a difference.</source>
        <translation>A live or read-only value, or one a parameter list leaves out: shown, never counted as a difference.</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ConnectionDialog</name>
    <message>
        <source>Connect to a drive</source>
        <translation>Connect to a drive</translation>
    </message>
    <message>
        <source>&amp;Recent connections</source>
        <translation>&amp;Recent connections</translation>
    </message>
    <message>
        <source>&amp;Serial port</source>
        <translation>&amp;Serial port</translation>
    </message>
    <message>
        <source>&amp;TCP</source>
        <translation>&amp;TCP</translation>
    </message>
    <message>
        <source>Si&amp;mulated drive</source>
        <translation>Si&amp;mulated drive</translation>
    </message>
    <message>
        <source>HSP5</source>
        <translation>HSP5</translation>
    </message>
    <message>
        <source>DIN66019II</source>
        <translation>DIN66019II</translation>
    </message>
    <message>
        <source>DIN66019</source>
        <translation>DIN66019</translation>
    </message>
    <message>
        <source>The drive&apos;s address on a DIN66019(II) bus, 0..239</source>
        <translation>The drive&apos;s address on a DIN66019(II) bus, 0..239</translation>
    </message>
    <message>
        <source>&amp;Find drives...</source>
        <translation>&amp;Find drives...</translation>
    </message>
    <message>
        <source>Ask every address 0..239 on the bus which drives answer</source>
        <translation>Ask every address 0..239 on the bus which drives answer</translation>
    </message>
    <message>
        <source>Drive &amp;address:</source>
        <translation>Drive &amp;address:</translation>
    </message>
    <message>
        <source>&amp;Protocol:</source>
        <translation>&amp;Protocol:</translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation>&amp;Connect</translation>
    </message>
    <message>
        <source>The serial port, or type a device such as /dev/ttyUSB0 or COM3</source>
        <translation>The serial port, or type a device such as /dev/ttyUSB0 or COM3</translation>
    </message>
    <message>
        <source>R&amp;efresh</source>
        <translation>R&amp;efresh</translation>
    </message>
    <message>
        <source>Look for serial ports again</source>
        <translation>Look for serial ports again</translation>
    </message>
    <message>
        <source>P&amp;ort:</source>
        <translation>P&amp;ort:</translation>
    </message>
    <message>
        <source>&amp;Baud rate:</source>
        <translation>&amp;Baud rate:</translation>
    </message>
    <message>
        <source>host name or IP address of the serial device server</source>
        <translation>host name or IP address of the serial device server</translation>
    </message>
    <message>
        <source>&amp;Host:</source>
        <translation>&amp;Host:</translation>
    </message>
    <message>
        <source>Po&amp;rt:</source>
        <translation>Po&amp;rt:</translation>
    </message>
    <message>
        <source>A simulated KEB COMBIVERT F5 running inside DriveDesk: every parameter, password levels, eight sets and a motor to watch. Nothing needs to be plugged in.</source>
        <translation>A simulated KEB COMBIVERT F5 running inside DriveDesk: every parameter, password levels, eight sets and a motor to watch. Nothing needs to be plugged in.</translation>
    </message>
    <message>
        <source>no serial port found</source>
        <translation>no serial port found</translation>
    </message>
    <message>
        <source>(none yet)</source>
        <translation>(none yet)</translation>
    </message>
    <message>
        <source>No serial port was found. Plug in the adapter and press Refresh, or type the device (e.g. /dev/ttyUSB0 or COM3).</source>
        <translation>No serial port was found. Plug in the adapter and press Refresh, or type the device (e.g. /dev/ttyUSB0 or COM3).</translation>
    </message>
    <message>
        <source>Choose the serial port the drive is connected to.</source>
        <translation>Choose the serial port the drive is connected to.</translation>
    </message>
    <message>
        <source>Enter the host name or IP address of the serial device server.</source>
        <translation>Enter the host name or IP address of the serial device server.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a host name or IP address.</source>
        <translation>&quot;%1&quot; is not a host name or IP address.</translation>
    </message>
    <message>
        <source>Finding drives needs a DIN66019II or DIN66019 bus: HSP5 is point to point. Choose the protocol first.</source>
        <translation>Finding drives needs a DIN66019II or DIN66019 bus: HSP5 is point to point. Choose the protocol first.</translation>
    </message>
    <message>
        <source>The drive has DriveDesk&apos;s HSP5 e&amp;xtensions</source>
        <translation>The drive has DriveDesk&apos;s HSP5 e&amp;xtensions</translation>
    </message>
    <message>
        <source>Services 13, 14, 19-21 and 51-53, which the HSP5 specification does not define. Only for a drive known to have them: a drive without them cannot tell where such a request ends and loses the requests that follow it.</source>
        <translation>Services 13, 14, 19-21 and 51-53, which the HSP5 specification does not define. Only for a drive known to have them: a drive without them cannot tell where such a request ends and loses the requests that follow it.</translation>
    </message>
    <message>
        <source>Automatic tries 38400, 19200, 9600, 57600 and 115200 Bd and takes the rate the drive answers at</source>
        <translation>Automatic tries 38400, 19200, 9600, 57600 and 115200 Bd and takes the rate the drive answers at</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatic</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a baud rate: enter a number such as 38400, or choose Automatic.</source>
        <translation>&quot;%1&quot; is not a baud rate: enter a number such as 38400, or choose Automatic.</translation>
    </message>
</context>
<context>
    <name>DriveDesk::DocumentEditor</name>
    <message>
        <source>the file has no parameter %1</source>
        <translation>the file has no parameter %1</translation>
    </message>
    <message>
        <source>Change %1 to %2%3</source>
        <translation>Change %1 to %2%3</translation>
    </message>
    <message>
        <source>%1 = %2 in the file%3; save to keep it</source>
        <translation>%1 = %2 in the file%3; save to keep it</translation>
    </message>
    <message>
        <source>Not reset: the file has no parameter %1</source>
        <translation>Not reset: the file has no parameter %1</translation>
    </message>
    <message>
        <source>Reset %1 to its default%2</source>
        <translation>Reset %1 to its default%2</translation>
    </message>
    <message>
        <source>%1 holds its default already%2</source>
        <translation>%1 holds its default already%2</translation>
    </message>
    <message>
        <source>%1 reset to its default in the file%2</source>
        <translation>%1 reset to its default in the file%2</translation>
    </message>
    <message>
        <source>Copy set %1 to set %2</source>
        <translation>Copy set %1 to set %2</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) read-only or locked</source>
        <translation>
            <numerusform>%n value read-only or locked</numerusform>
            <numerusform>%n values read-only or locked</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) of set %1 not known</source>
        <translation>
            <numerusform>%n value of set %1 not known</numerusform>
            <numerusform>%n values of set %1 not known</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) outside the limits</source>
        <translation>
            <numerusform>%n value outside the limits</numerusform>
            <numerusform>%n values outside the limits</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Copied %n value(s) from set %1 to set %2 in the file</source>
        <translation>
            <numerusform>Copied %n value from set %1 to set %2 in the file</numerusform>
            <numerusform>Copied %n values from set %1 to set %2 in the file</numerusform>
        </translation>
    </message>
    <message>
        <source>Set %1 and set %2 hold the same values: nothing to copy</source>
        <translation>Set %1 and set %2 hold the same values: nothing to copy</translation>
    </message>
    <message>
        <source>; left as they are: %1</source>
        <translation>; left as they are: %1</translation>
    </message>
    <message>
        <source>Undone in the file: %1</source>
        <translation>Undone in the file: %1</translation>
    </message>
    <message>
        <source>Redone in the file: %1</source>
        <translation>Redone in the file: %1</translation>
    </message>
    <message>
        <source>%1; the file is unchanged</source>
        <translation>%1; the file is unchanged</translation>
    </message>
</context>
<context>
    <name>DriveDesk::DownloadDialog</name>
    <message>
        <source>Download to the Drive</source>
        <translation>Download to the Drive</translation>
    </message>
    <message>
        <source>Sets to write:</source>
        <translation>Sets to write:</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Sets</source>
        <translation>Sets</translation>
    </message>
    <message>
        <source>Drive now</source>
        <translation>Drive now</translation>
    </message>
    <message>
        <source>To write</source>
        <translation>To write</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Note</translation>
    </message>
    <message>
        <source>Write</source>
        <translation>Write</translation>
    </message>
    <message>
        <source>Reading the drive&apos;s values to compare them with the file...</source>
        <translation>Reading the drive&apos;s values to compare them with the file...</translation>
    </message>
    <message>
        <source>Writing to the drive: %1</source>
        <translation>Writing to the drive: %1</translation>
    </message>
    <message>
        <source>always written</source>
        <translation>always written</translation>
    </message>
    <message>
        <source>left: %1</source>
        <translation>left: %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;The file does not fit the drive:&lt;/b&gt;&lt;ul&gt;%1&lt;/ul&gt;</source>
        <translation>&lt;b&gt;The file does not fit the drive:&lt;/b&gt;&lt;ul&gt;%1&lt;/ul&gt;</translation>
    </message>
    <message>
        <source>Nothing will be written unless you overrule the checks.</source>
        <translation>Nothing will be written unless you overrule the checks.</translation>
    </message>
    <message>
        <source>Look at what will be written, then write it.</source>
        <translation>Look at what will be written, then write it.</translation>
    </message>
    <message>
        <source>The drive holds the file&apos;s values already.</source>
        <translation>The drive holds the file&apos;s values already.</translation>
    </message>
    <message numerus="yes">
        <source>&amp;Write %n Value(s)</source>
        <translation>
            <numerusform>&amp;Write %n Value</numerusform>
            <numerusform>&amp;Write %n Values</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>&amp;Stop</translation>
    </message>
    <message>
        <source>Writing to the drive...</source>
        <translation>Writing to the drive...</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Close</translation>
    </message>
    <message>
        <source>Download finished: everything to write was written and read back.</source>
        <translation>Download finished: everything to write was written and read back.</translation>
    </message>
    <message>
        <source>The download did not write everything. The report says what the drive holds.</source>
        <translation>The download did not write everything. The report says what the drive holds.</translation>
    </message>
    <message>
        <source>Stopping after the value on its way...</source>
        <translation>Stopping after the value on its way...</translation>
    </message>
    <message>
        <source>Writes %1 to the drive, each read back.</source>
        <translation>Writes %1 to the drive, each read back.</translation>
    </message>
    <message>
        <source>Write all the same (the checks above are &amp;overruled)</source>
        <translation>Write all the same (the checks above are &amp;overruled)</translation>
    </message>
</context>
<context>
    <name>DriveDesk::DownloadFeature</name>
    <message>
        <source>Write a parameter file&apos;s values to the drive, after a last look at what differs</source>
        <translation>Write a parameter file&apos;s values to the drive, after a last look at what differs</translation>
    </message>
    <message>
        <source>Download File to Drive</source>
        <translation>Download File to Drive</translation>
    </message>
    <message>
        <source>Nothing was written: %1</source>
        <translation>Nothing was written: %1</translation>
    </message>
    <message>
        <source>A download is on its way already.</source>
        <translation>A download is on its way already.</translation>
    </message>
    <message>
        <source>Nothing was written: no drive is connected.</source>
        <translation>Nothing was written: no drive is connected.</translation>
    </message>
    <message>
        <source>Download finished; the values are read again.</source>
        <translation>Download finished; the values are read again.</translation>
    </message>
    <message>
        <source>the values chosen in the compare window</source>
        <translation>the values chosen in the compare window</translation>
    </message>
    <message>
        <source>Down&amp;load File to Drive...</source>
        <translation>Down&amp;load File to Drive...</translation>
    </message>
    <message>
        <source>the values of %1</source>
        <translation>the values of %1</translation>
    </message>
    <message>
        <source>download of %1</source>
        <translation>download of %1</translation>
    </message>
</context>
<context>
    <name>DriveDesk::DownloadRun</name>
    <message>
        <source>writing %1 of %2</source>
        <translation>writing %1 of %2</translation>
    </message>
    <message>
        <source>no drive is connected; nothing was written</source>
        <translation>no drive is connected; nothing was written</translation>
    </message>
    <message>
        <source>stopped before anything was written</source>
        <translation>stopped before anything was written</translation>
    </message>
    <message>
        <source>no answer</source>
        <translation>no answer</translation>
    </message>
    <message>
        <source>the drive could not be read (%1); nothing was written</source>
        <translation>the drive could not be read (%1); nothing was written</translation>
    </message>
    <message>
        <source>the drive is no longer connected; nothing was written</source>
        <translation>the drive is no longer connected; nothing was written</translation>
    </message>
    <message>
        <source>stopped by the user</source>
        <translation>stopped by the user</translation>
    </message>
    <message>
        <source>the journal cannot record the download: %1; nothing was written</source>
        <translation>the journal cannot record the download: %1; nothing was written</translation>
    </message>
    <message>
        <source>%1 is not described</source>
        <translation>%1 is not described</translation>
    </message>
    <message>
        <source>the download ended first</source>
        <translation>the download ended first</translation>
    </message>
    <message>
        <source>the journal cannot record the download: %1</source>
        <translation>the journal cannot record the download: %1</translation>
    </message>
</context>
<context>
    <name>DriveDesk::DriveInfoDialog</name>
    <message>
        <source>Connection</source>
        <translation>Connection</translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>Protocol</translation>
    </message>
    <message>
        <source>Drive address</source>
        <translation>Drive address</translation>
    </message>
    <message>
        <source>Parameter groups</source>
        <translation>Parameter groups</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameters</translation>
    </message>
    <message>
        <source>Scan incomplete</source>
        <translation>Scan incomplete</translation>
    </message>
    <message>
        <source>Drive information</source>
        <translation>Drive information</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Copy</translation>
    </message>
    <message>
        <source>Metadata</source>
        <translation>Metadata</translation>
    </message>
    <message>
        <source>from the metadata cache of this kind of drive</source>
        <translation>from the metadata cache of this kind of drive</translation>
    </message>
    <message>
        <source>read from the drive</source>
        <translation>read from the drive</translation>
    </message>
</context>
<context>
    <name>DriveDesk::DriveScanner</name>
    <message>
        <source>identification</source>
        <translation>identification</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>cancelled</translation>
    </message>
    <message>
        <source>group page %1h</source>
        <translation>group page %1h</translation>
    </message>
    <message>
        <source>group page %1h: %2</source>
        <translation>group page %1h: %2</translation>
    </message>
    <message>
        <source>group %1: name</source>
        <translation>group %1: name</translation>
    </message>
    <message>
        <source>name</source>
        <translation>name</translation>
    </message>
    <message>
        <source>limits</source>
        <translation>limits</translation>
    </message>
    <message>
        <source>default value</source>
        <translation>default value</translation>
    </message>
    <message>
        <source>properties</source>
        <translation>properties</translation>
    </message>
    <message>
        <source>values: not read, the properties are unknown</source>
        <translation>values: not read, the properties are unknown</translation>
    </message>
    <message>
        <source>display scaling</source>
        <translation>display scaling</translation>
    </message>
    <message>
        <source>plaintext indices</source>
        <translation>plaintext indices</translation>
    </message>
    <message>
        <source>value</source>
        <translation>value</translation>
    </message>
    <message>
        <source>value of set %1</source>
        <translation>value of set %1</translation>
    </message>
    <message>
        <source>plaintexts: the drive names %1 definitions, only %2 can be read</source>
        <translation>plaintexts: the drive names %1 definitions, only %2 can be read</translation>
    </message>
    <message>
        <source>plaintext definition %1</source>
        <translation>plaintext definition %1</translation>
    </message>
    <message>
        <source>plaintext %1.%2</source>
        <translation>plaintext %1.%2</translation>
    </message>
    <message>
        <source>group %1: parameter %2</source>
        <translation>group %1: parameter %2</translation>
    </message>
    <message>
        <source>the answer carries no %1</source>
        <translation>the answer carries no %1</translation>
    </message>
    <message numerus="yes">
        <source>%1 (and %n more)</source>
        <translation>
            <numerusform>%1 (and %n more)</numerusform>
            <numerusform>%1 (and %n more)</numerusform>
        </translation>
    </message>
    <message>
        <source>identification %1h</source>
        <translation>identification %1h</translation>
    </message>
    <message>
        <source>values of sets %1</source>
        <translation>values of sets %1</translation>
    </message>
    <message>
        <source>%1: not confirmed when read again on a line with errors</source>
        <translation>%1: not confirmed when read again on a line with errors</translation>
    </message>
    <message>
        <source>the answers did not agree</source>
        <translation>the answers did not agree</translation>
    </message>
    <message>
        <source>implausible answer: %1</source>
        <translation>implausible answer: %1</translation>
    </message>
    <message>
        <source>default value: %1</source>
        <translation>default value: %1</translation>
    </message>
    <message>
        <source>value of set %1: %2</source>
        <translation>value of set %1: %2</translation>
    </message>
    <message>
        <source>group %1: %2 of %3 parameters found</source>
        <translation>group %1: %2 of %3 parameters found</translation>
    </message>
    <message>
        <source>group %1: %2 of %3 parameters found; no answer for %4 (%5)</source>
        <translation>group %1: %2 of %3 parameters found; no answer for %4 (%5)</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) without a valid answer (%1)</source>
        <translation>
            <numerusform>%n parameter without a valid answer (%1)</numerusform>
            <numerusform>%n parameters without a valid answer (%1)</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: not confirmed: the drive changes it by itself, and on a line with errors no two reads agreed</source>
        <translation>%1: not confirmed: the drive changes it by itself, and on a line with errors no two reads agreed</translation>
    </message>
</context>
<context>
    <name>DriveDesk::DriveSession</name>
    <message>
        <source>the scan was cancelled</source>
        <translation>the scan was cancelled</translation>
    </message>
</context>
<context>
    <name>DriveDesk::DriveState</name>
    <message>
        <source>there is no parameter %1</source>
        <translation>there is no parameter %1</translation>
    </message>
    <message>
        <source>the drive holds %1, not %2</source>
        <translation>the drive holds %1, not %2</translation>
    </message>
</context>
<context>
    <name>DriveDesk::EditController</name>
    <message>
        <source>Not written: this drive has no parameter %1</source>
        <translation>Not written: this drive has no parameter %1</translation>
    </message>
    <message>
        <source>%1 not written: no set chosen</source>
        <translation>%1 not written: no set chosen</translation>
    </message>
    <message>
        <source>Not reset: this drive has no parameter %1</source>
        <translation>Not reset: this drive has no parameter %1</translation>
    </message>
    <message>
        <source>%1 not reset: no set chosen</source>
        <translation>%1 not reset: no set chosen</translation>
    </message>
    <message>
        <source>Reset %1 to its default%2</source>
        <translation>Reset %1 to its default%2</translation>
    </message>
    <message>
        <source>Write %1 = %2%3</source>
        <translation>Write %1 = %2%3</translation>
    </message>
    <message>
        <source>%1%2: the value before the change is not known, so it stays as it is</source>
        <translation>%1%2: the value before the change is not known, so it stays as it is</translation>
    </message>
    <message>
        <source>Undone: %1</source>
        <translation>Undone: %1</translation>
    </message>
    <message>
        <source>Redone: %1</source>
        <translation>Redone: %1</translation>
    </message>
    <message>
        <source>Undo failed: %1: %2</source>
        <translation>Undo failed: %1: %2</translation>
    </message>
    <message>
        <source>Redo failed: %1: %2</source>
        <translation>Redo failed: %1: %2</translation>
    </message>
    <message>
        <source>Still copying set %1 to set %2</source>
        <translation>Still copying set %1 to set %2</translation>
    </message>
    <message>
        <source>Still reading the values</source>
        <translation>Still reading the values</translation>
    </message>
    <message>
        <source>Cannot copy set %1 to set %2: the sets are 0 to %3</source>
        <translation>Cannot copy set %1 to set %2: the sets are 0 to %3</translation>
    </message>
    <message>
        <source>Cannot copy set %1 onto itself</source>
        <translation>Cannot copy set %1 onto itself</translation>
    </message>
    <message>
        <source>Copy set %1 to set %2</source>
        <translation>Copy set %1 to set %2</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Set %2 holds the values of set %1 already</source>
        <translation>Set %2 holds the values of set %1 already</translation>
    </message>
    <message numerus="yes">
        <source>Set %1 copied to set %2: %n value(s) written</source>
        <translation>
            <numerusform>Set %1 copied to set %2: %n value written</numerusform>
            <numerusform>Set %1 copied to set %2: %n values written</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n refused (%1)</source>
        <translation>
            <numerusform>%n refused (%1)</numerusform>
            <numerusform>%n refused (%1)</numerusform>
        </translation>
    </message>
    <message>
        <source>stopped: %1</source>
        <translation>stopped: %1</translation>
    </message>
    <message numerus="yes">
        <source>cancelled, %n value(s) not copied</source>
        <translation>
            <numerusform>cancelled, %n value not copied</numerusform>
            <numerusform>cancelled, %n values not copied</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) left as they are: read-only or above the password level</source>
        <translation>
            <numerusform>%n parameter left as it is: read-only or above the password level</numerusform>
            <numerusform>%n parameters left as they are: read-only or above the password level</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) left out: the value in set %1 was never read</source>
        <translation>
            <numerusform>%n parameter left out: the value in set %1 was never read</numerusform>
            <numerusform>%n parameters left out: the value in set %1 was never read</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) read</source>
        <translation>
            <numerusform>%n value read</numerusform>
            <numerusform>%n values read</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n could not be read (first: %1%2: %3)</source>
        <translation>
            <numerusform>%n could not be read (%1%2: %3)</numerusform>
            <numerusform>%n could not be read (first: %1%2: %3)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>cancelled, %n value(s) not read</source>
        <translation>
            <numerusform>cancelled, %n value not read</numerusform>
            <numerusform>cancelled, %n values not read</numerusform>
        </translation>
    </message>
    <message>
        <source>; the drive changes this value itself, so the write cannot be undone</source>
        <translation>; the drive changes this value itself, so the write cannot be undone</translation>
    </message>
    <message>
        <source>this drive has no parameter %1</source>
        <translation>this drive has no parameter %1</translation>
    </message>
    <message>
        <source>Set %1 not copied to set %2: %3</source>
        <translation>Set %1 not copied to set %2: %3</translation>
    </message>
    <message>
        <source>the copy was cancelled</source>
        <translation>the copy was cancelled</translation>
    </message>
</context>
<context>
    <name>DriveDesk::EditingFeature</name>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Undo</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Redo</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Undo</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Redo</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Undo %1</translation>
    </message>
    <message>
        <source>Undo %1</source>
        <translation>Undo %1</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>&amp;Redo %1</translation>
    </message>
    <message>
        <source>Redo %1</source>
        <translation>Redo %1</translation>
    </message>
    <message>
        <source>Reset to &amp;Default</source>
        <translation>Reset to &amp;Default</translation>
    </message>
    <message>
        <source>Set the selected values to the drive&apos;s default</source>
        <translation>Set the selected values to the drive&apos;s default</translation>
    </message>
    <message>
        <source>&amp;Write to Sets...</source>
        <translation>&amp;Write to Sets...</translation>
    </message>
    <message>
        <source>Write a value to several parameter sets at once</source>
        <translation>Write a value to several parameter sets at once</translation>
    </message>
    <message>
        <source>&amp;Copy Set...</source>
        <translation>&amp;Copy Set...</translation>
    </message>
    <message>
        <source>Copy every set-programmable value from one set to another</source>
        <translation>Copy every set-programmable value from one set to another</translation>
    </message>
    <message numerus="yes">
        <source>Not reset, read-only or above the password level in force: %1 and %n more</source>
        <translation>
            <numerusform>Not reset, read-only or above the password level in force: %1 and %n more</numerusform>
            <numerusform>Not reset, read-only or above the password level in force: %1 and %n more</numerusform>
        </translation>
    </message>
    <message>
        <source>Not reset, read-only or above the password level in force: %1</source>
        <translation>Not reset, read-only or above the password level in force: %1</translation>
    </message>
    <message>
        <source>%1 is not set-programmable: it holds one value for every set.</source>
        <translation>%1 is not set-programmable: it holds one value for every set.</translation>
    </message>
    <message>
        <source>%1 has no value read in set %2 to write.</source>
        <translation>%1 has no value read in set %2 to write.</translation>
    </message>
    <message>
        <source>Write to Sets</source>
        <translation>Write to Sets</translation>
    </message>
    <message>
        <source>Write %1 to %2 in:</source>
        <translation>Write %1 to %2 in:</translation>
    </message>
    <message>
        <source>Copy Set</source>
        <translation>Copy Set</translation>
    </message>
    <message>
        <source>Copy every set-programmable value you may change from one set to another:</source>
        <translation>Copy every set-programmable value you may change from one set to another:</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ExportFeature</name>
    <message>
        <source>Export as &amp;CSV...</source>
        <translation>Export as &amp;CSV...</translation>
    </message>
    <message>
        <source>Write every parameter with its unit and each set&apos;s value as shown to a CSV file for a spreadsheet</source>
        <translation>Write every parameter with its unit and each set&apos;s value as shown to a CSV file for a spreadsheet</translation>
    </message>
    <message>
        <source>Export as CSV</source>
        <translation>Export as CSV</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV files (*.csv)</translation>
    </message>
    <message>
        <source>Not exported: %1. The file on disk is as it was.</source>
        <translation>Not exported: %1. The file on disk is as it was.</translation>
    </message>
    <message numerus="yes">
        <source>Exported %n parameter(s) to %1.</source>
        <translation>
            <numerusform>Exported %n parameter to %1.</numerusform>
            <numerusform>Exported %n parameters to %1.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>DriveDesk::FilterBar</name>
    <message>
        <source>Search every group by id, name or value</source>
        <translation>Search every group by id, name or value</translation>
    </message>
    <message>
        <source>&amp;Find...</source>
        <translation>&amp;Find...</translation>
    </message>
    <message>
        <source>Search parameters by id, name or value</source>
        <translation>Search parameters by id, name or value</translation>
    </message>
    <message>
        <source>Search every group by id (ru.3), name or value as you type (%1)</source>
        <translation>Search every group by id (ru.3), name or value as you type (%1)</translation>
    </message>
    <message>
        <source>&amp;Differs from Default</source>
        <translation>&amp;Differs from Default</translation>
    </message>
    <message>
        <source>F&amp;avourites</source>
        <translation>F&amp;avourites</translation>
    </message>
    <message>
        <source>F&amp;avourites Only</source>
        <translation>F&amp;avourites Only</translation>
    </message>
    <message>
        <source>Only the parameters marked with a star</source>
        <translation>Only the parameters marked with a star</translation>
    </message>
    <message>
        <source>&amp;Hide Parameters above Password Level</source>
        <translation>&amp;Hide Parameters above Password Level</translation>
    </message>
    <message>
        <source>Hide parameters the password level in force does not open; otherwise they are greyed out</source>
        <translation>Hide parameters the password level in force does not open; otherwise they are greyed out</translation>
    </message>
    <message>
        <source>Ra&amp;w values</source>
        <translation>Ra&amp;w values</translation>
    </message>
    <message>
        <source>Show &amp;Raw Values</source>
        <translation>Show &amp;Raw Values</translation>
    </message>
    <message>
        <source>Show the raw integers the drive holds instead of scaled values and plaintexts</source>
        <translation>Show the raw integers the drive holds instead of scaled values and plaintexts</translation>
    </message>
    <message>
        <source>Only settings whose value differs from the default (not read-only or live values)</source>
        <translation>Only settings whose value differs from the default (not read-only or live values)</translation>
    </message>
    <message>
        <source>D&amp;iffers from default</source>
        <translation>D&amp;iffers from default</translation>
    </message>
    <message>
        <source>Hide above &amp;password level</source>
        <translation>Hide above &amp;password level</translation>
    </message>
</context>
<context>
    <name>DriveDesk::FindDrivesDialog</name>
    <message>
        <source>the %1 bus on %2 at %3 baud</source>
        <translation>the %1 bus on %2 at %3 baud</translation>
    </message>
    <message>
        <source>the %1 bus behind %2</source>
        <translation>the %1 bus behind %2</translation>
    </message>
    <message>
        <source>the simulated %1 bus</source>
        <translation>the simulated %1 bus</translation>
    </message>
    <message>
        <source>Find drives</source>
        <translation>Find drives</translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>&amp;Stop</translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation>&amp;Connect</translation>
    </message>
    <message>
        <source>Search &amp;again</source>
        <translation>Search &amp;again</translation>
    </message>
    <message>
        <source>Drives that answered:</source>
        <translation>Drives that answered:</translation>
    </message>
    <message>
        <source>Asking every address %2..%3 on %1 whether a drive answers.</source>
        <translation>Asking every address %2..%3 on %1 whether a drive answers.</translation>
    </message>
    <message>
        <source>not connected to the bus</source>
        <translation>not connected to the bus</translation>
    </message>
    <message>
        <source>Opening the connection...</source>
        <translation>Opening the connection...</translation>
    </message>
    <message>
        <source>Searching...</source>
        <translation>Searching...</translation>
    </message>
    <message>
        <source>Stopped.</source>
        <translation>Stopped.</translation>
    </message>
    <message>
        <source>The search stopped: %1</source>
        <translation>The search stopped: %1</translation>
    </message>
    <message>
        <source>No drive answered. Check the wiring, the baud rate and the protocol.</source>
        <translation>No drive answered. Check the wiring, the baud rate and the protocol.</translation>
    </message>
    <message numerus="yes">
        <source>%n drive(s) answered.</source>
        <translation>
            <numerusform>%n drive answered.</numerusform>
            <numerusform>%n drives answered.</numerusform>
        </translation>
    </message>
    <message>
        <source>Could not search: %1</source>
        <translation>Could not search: %1</translation>
    </message>
    <message>
        <source>Stopping...</source>
        <translation>Stopping...</translation>
    </message>
    <message>
        <source>Drive %1, connected now</source>
        <translation>Drive %1, connected now</translation>
    </message>
    <message>
        <source>Drive %1</source>
        <translation>Drive %1</translation>
    </message>
    <message>
        <source>gave no identification</source>
        <translation>gave no identification</translation>
    </message>
    <message numerus="yes">
        <source>Stopped after %1 of %2 addresses: %n drive(s) answered.</source>
        <translation>
            <numerusform>Stopped after %1 of %2 addresses: %n drive answered.</numerusform>
            <numerusform>Stopped after %1 of %2 addresses: %n drives answered.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>DriveDesk::GroupListModel</name>
    <message>
        <source>All parameters</source>
        <translation>All parameters</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>Group</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameters</translation>
    </message>
</context>
<context>
    <name>DriveDesk::HexValueEdit</name>
    <message>
        <source>Hexadecimal, %1 .. %2</source>
        <translation>Hexadecimal, %1 .. %2</translation>
    </message>
</context>
<context>
    <name>DriveDesk::JournalDock</name>
    <message>
        <source>Journal</source>
        <translation>Journal</translation>
    </message>
    <message>
        <source>Drive:</source>
        <translation>Drive:</translation>
    </message>
    <message>
        <source>serial number, link or link@address</source>
        <translation>serial number, link or link@address</translation>
    </message>
    <message>
        <source>Parameter:</source>
        <translation>Parameter:</translation>
    </message>
    <message>
        <source>op.28 or 0x0A1C</source>
        <translation>op.28 or 0x0A1C</translation>
    </message>
    <message>
        <source>User:</source>
        <translation>User:</translation>
    </message>
    <message>
        <source>login name</source>
        <translation>login name</translation>
    </message>
    <message>
        <source>Since:</source>
        <translation>Since:</translation>
    </message>
    <message>
        <source>2026-11-24 or 2026-11-24 10:42</source>
        <translation>2026-11-24 or 2026-11-24 10:42</translation>
    </message>
    <message>
        <source>Until:</source>
        <translation>Until:</translation>
    </message>
    <message>
        <source>Search:</source>
        <translation>Search:</translation>
    </message>
    <message>
        <source>any field of the entries shown</source>
        <translation>any field of the entries shown</translation>
    </message>
    <message>
        <source>This Drive</source>
        <translation>This Drive</translation>
    </message>
    <message>
        <source>Show the entries of the connected drive</source>
        <translation>Show the entries of the connected drive</translation>
    </message>
    <message>
        <source>Load Older</source>
        <translation>Load Older</translation>
    </message>
    <message numerus="yes">
        <source>Read the %n entries before the oldest shown</source>
        <translation>
            <numerusform>Read the %n entry before the oldest shown</numerusform>
            <numerusform>Read the %n entries before the oldest shown</numerusform>
        </translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>Refresh</translation>
    </message>
    <message>
        <source>Revert...</source>
        <translation>Revert...</translation>
    </message>
    <message>
        <source>Write the values before the selected entries back to the drive, after a last look at what will change</source>
        <translation>Write the values before the selected entries back to the drive, after a last look at what will change</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not after &apos;%2&apos;</source>
        <translation>&apos;%1&apos; is not after &apos;%2&apos;</translation>
    </message>
    <message>
        <source>Reading the journal...</source>
        <translation>Reading the journal...</translation>
    </message>
    <message numerus="yes">
        <source>%n entries</source>
        <translation>
            <numerusform>%n entry</numerusform>
            <numerusform>%n entries</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n entries match the search</source>
        <translation>
            <numerusform>%1 of %n entry matches the search</numerusform>
            <numerusform>%1 of %n entries match the search</numerusform>
        </translation>
    </message>
    <message>
        <source>older ones not read yet</source>
        <translation>older ones not read yet</translation>
    </message>
</context>
<context>
    <name>DriveDesk::JournalFeature</name>
    <message>
        <source>&amp;Journal</source>
        <translation>&amp;Journal</translation>
    </message>
    <message>
        <source>The values written to drives: who, when, before and after</source>
        <translation>The values written to drives: who, when, before and after</translation>
    </message>
    <message>
        <source>Revert</source>
        <translation>Revert</translation>
    </message>
    <message>
        <source>Nothing was written: no drive is connected.</source>
        <translation>Nothing was written: no drive is connected.</translation>
    </message>
    <message>
        <source>Nothing was written:
%1</source>
        <translation>Nothing was written:
%1</translation>
    </message>
</context>
<context>
    <name>DriveDesk::JournalTableModel</name>
    <message>
        <source>active</source>
        <translation>active</translation>
    </message>
    <message>
        <source>(password)</source>
        <translation>(password)</translation>
    </message>
    <message>
        <source>%1 on %2, software %3, serial number %4</source>
        <translation>%1 on %2, software %3, serial number %4</translation>
    </message>
    <message>
        <source>Answered %1</source>
        <translation>Answered %1</translation>
    </message>
    <message>
        <source>Entry</source>
        <translation>Entry</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Time</translation>
    </message>
    <message>
        <source>User</source>
        <translation>User</translation>
    </message>
    <message>
        <source>Host</source>
        <translation>Host</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>Job</source>
        <translation>Job</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>Drive</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Set</source>
        <translation>Set</translation>
    </message>
    <message>
        <source>Before</source>
        <translation>Before</translation>
    </message>
    <message>
        <source>Written</source>
        <translation>Written</translation>
    </message>
    <message>
        <source>Read back</source>
        <translation>Read back</translation>
    </message>
    <message>
        <source>Outcome</source>
        <translation>Outcome</translation>
    </message>
</context>
<context>
    <name>DriveDesk::MainWindow</name>
    <message>
        <source>DriveDesk</source>
        <translation>DriveDesk</translation>
    </message>
    <message>
        <source>Not connected. Choose Connect... (%1) to reach a drive or the simulated one.</source>
        <translation>Not connected. Choose Connect... (%1) to reach a drive or the simulated one.</translation>
    </message>
    <message>
        <source>Connected. Reading the drive...</source>
        <translation>Connected. Reading the drive...</translation>
    </message>
    <message>
        <source>Reconnected to %1; reading the values again.</source>
        <translation>Reconnected to %1; reading the values again.</translation>
    </message>
    <message>
        <source>Reading the drive...</source>
        <translation>Reading the drive...</translation>
    </message>
    <message>
        <source>Connecting...</source>
        <translation>Connecting...</translation>
    </message>
    <message>
        <source>Connecting to %1...</source>
        <translation>Connecting to %1...</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>Not connected</translation>
    </message>
    <message>
        <source>Connected: %1</source>
        <translation>Connected: %1</translation>
    </message>
    <message>
        <source>Connection lost</source>
        <translation>Connection lost</translation>
    </message>
    <message>
        <source>Reading the drive: %1</source>
        <translation>Reading the drive: %1</translation>
    </message>
    <message>
        <source>%1 - DriveDesk</source>
        <translation>%1 - DriveDesk</translation>
    </message>
    <message>
        <source>The drive reported no parameters.</source>
        <translation>The drive reported no parameters.</translation>
    </message>
    <message>
        <source>Nothing was read from the drive: %1.</source>
        <translation>Nothing was read from the drive: %1.</translation>
    </message>
    <message>
        <source>Nothing was read: %1. Press Refresh (%2) to read the drive.</source>
        <translation>Nothing was read: %1. Press Refresh (%2) to read the drive.</translation>
    </message>
    <message>
        <source>The connection to the drive was lost: %1. What was read stays shown; editing is off until the drive is reconnected.</source>
        <translation>The connection to the drive was lost: %1. What was read stays shown; editing is off until the drive is reconnected.</translation>
    </message>
    <message>
        <source>Connection lost: %1</source>
        <translation>Connection lost: %1</translation>
    </message>
    <message>
        <source>Could not connect: %1</source>
        <translation>Could not connect: %1</translation>
    </message>
    <message>
        <source>Could not connect to %1: %2</source>
        <translation>Could not connect to %1: %2</translation>
    </message>
    <message>
        <source>Disconnected from %1. What was read stays shown.</source>
        <translation>Disconnected from %1. What was read stays shown.</translation>
    </message>
    <message>
        <source>&amp;Connect...</source>
        <translation>&amp;Connect...</translation>
    </message>
    <message>
        <source>Connect to a drive or the simulated one</source>
        <translation>Connect to a drive or the simulated one</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Disconnect</translation>
    </message>
    <message>
        <source>&amp;Find Drives...</source>
        <translation>&amp;Find Drives...</translation>
    </message>
    <message>
        <source>Look for drives at the addresses 0..239 of a DIN66019II bus</source>
        <translation>Look for drives at the addresses 0..239 of a DIN66019II bus</translation>
    </message>
    <message>
        <source>&amp;Refresh</source>
        <translation>&amp;Refresh</translation>
    </message>
    <message>
        <source>Read every value from the drive again</source>
        <translation>Read every value from the drive again</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quit</translation>
    </message>
    <message>
        <source>&amp;About DriveDesk</source>
        <translation>&amp;About DriveDesk</translation>
    </message>
    <message>
        <source>&amp;Drive</source>
        <translation>&amp;Drive</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Edit</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;View</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Help</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>About &amp;Qt</translation>
    </message>
    <message>
        <source>Main Toolbar</source>
        <translation>Main Toolbar</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Language</translation>
    </message>
    <message>
        <source>DriveDesk uses the new language from its next start on: the window&apos;s texts and the drive&apos;s own texts.</source>
        <translation>DriveDesk uses the new language from its next start on: the window&apos;s texts and the drive&apos;s own texts.</translation>
    </message>
    <message>
        <source>About DriveDesk</source>
        <translation>About DriveDesk</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;DriveDesk&lt;/b&gt; %1&lt;/p&gt;&lt;p&gt;Reads and edits the parameters of KEB frequency inverters over HSP5, DIN66019II and DIN66019, and ships a simulated COMBIVERT F5.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;DriveDesk&lt;/b&gt; %1&lt;/p&gt;&lt;p&gt;Reads and edits the parameters of KEB frequency inverters over HSP5, DIN66019II and DIN66019, and ships a simulated COMBIVERT F5.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Read &amp;Metadata Again</source>
        <translation>Read &amp;Metadata Again</translation>
    </message>
    <message>
        <source>Read the groups, names, limits and texts from the drive instead of the metadata cache</source>
        <translation>Read the groups, names, limits and texts from the drive instead of the metadata cache</translation>
    </message>
    <message>
        <source>Metadata from cache</source>
        <translation>Metadata from cache</translation>
    </message>
    <message>
        <source>The groups, names, limits and texts come from the metadata cache of this kind of drive; the values were read from the drive. Drive &gt; Read Metadata Again reads everything.</source>
        <translation>The groups, names, limits and texts come from the metadata cache of this kind of drive; the values were read from the drive. Drive &gt; Read Metadata Again reads everything.</translation>
    </message>
    <message numerus="yes">
        <source>Read %n parameter(s).</source>
        <translation>
            <numerusform>Read %n parameter.</numerusform>
            <numerusform>Read %n parameters.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The drive has %n group(s).</source>
        <translation>
            <numerusform>The drive has %n group.</numerusform>
            <numerusform>The drive has %n groups.</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Language (from the next start)</source>
        <translation>&amp;Language (from the next start)</translation>
    </message>
    <message>
        <source>Takes effect when DriveDesk starts again</source>
        <translation>Takes effect when DriveDesk starts again</translation>
    </message>
    <message>
        <source>Closing the connection to %1...</source>
        <translation>Closing the connection to %1...</translation>
    </message>
    <message>
        <source>Connected: %1; the drive is not answering</source>
        <translation>Connected: %1; the drive is not answering</translation>
    </message>
    <message numerus="yes">
        <source>the table shows the %n parameter(s) read</source>
        <translation>
            <numerusform>the table shows the %n parameter read</numerusform>
            <numerusform>the table shows the %n parameters read</numerusform>
        </translation>
    </message>
    <message>
        <source>The drive was read only in part (%1): %2. Read it again with Drive &gt; Read Metadata Again.</source>
        <translation>The drive was read only in part (%1): %2. Read it again with Drive &gt; Read Metadata Again.</translation>
    </message>
    <message>
        <source>Incomplete: %1</source>
        <translation>Incomplete: %1</translation>
    </message>
    <message>
        <source>The drive is not answering</source>
        <translation>The drive is not answering</translation>
    </message>
    <message>
        <source>The drive answers again.</source>
        <translation>The drive answers again.</translation>
    </message>
    <message>
        <source>Could not connect to %1: %2. What was shown before stays.</source>
        <translation>Could not connect to %1: %2. What was shown before stays.</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message numerus="yes">
        <source>Opened %1: %n parameter(s), no drive connected.</source>
        <translation>
            <numerusform>Opened %1: %n parameter, no drive connected.</numerusform>
            <numerusform>Opened %1: %n parameters, no drive connected.</numerusform>
        </translation>
    </message>
    <message>
        <source>Disconnected from %1 to show the parameter file %2.</source>
        <translation>Disconnected from %1 to show the parameter file %2.</translation>
    </message>
    <message>
        <source>No drive: parameter file</source>
        <translation>No drive: parameter file</translation>
    </message>
    <message>
        <source>The parameter file holds no parameters.</source>
        <translation>The parameter file holds no parameters.</translation>
    </message>
    <message>
        <source>%1[*] - DriveDesk</source>
        <translation>%1[*] - DriveDesk</translation>
    </message>
    <message>
        <source>Replace File</source>
        <translation>Replace File</translation>
    </message>
    <message>
        <source>%1 exists already. Replace it?</source>
        <translation>%1 exists already. Replace it?</translation>
    </message>
    <message>
        <source>&amp;Replace</source>
        <translation>&amp;Replace</translation>
    </message>
    <message>
        <source>DriveDesk parameter files (*.json)</source>
        <translation>DriveDesk parameter files (*.json)</translation>
    </message>
    <message>
        <source>Reconnected to %1; the drive was read only in part: reading it again.</source>
        <translation>Reconnected to %1; the drive was read only in part: reading it again.</translation>
    </message>
    <message>
        <source>Reading the drive again stopped (%1). The table keeps what was read before: every parameter with its limits, units and texts, and the values as last read.</source>
        <translation>Reading the drive again stopped (%1). The table keeps what was read before: every parameter with its limits, units and texts, and the values as last read.</translation>
    </message>
    <message>
        <source>Reading the drive again stopped: %1</source>
        <translation>Reading the drive again stopped: %1</translation>
    </message>
    <message>
        <source>Drive Inf&amp;ormation...</source>
        <translation>Drive Inf&amp;ormation...</translation>
    </message>
    <message>
        <source>The drive is not answering: the connection to %1 is open, but no valid answer came from the drive since %2 (nothing at all, or only what cannot be an answer). The values shown are the last read and are marked stale. This clears by itself when the drive answers again.</source>
        <translation>The drive is not answering: the connection to %1 is open, but no valid answer came from the drive since %2 (nothing at all, or only what cannot be an answer). The values shown are the last read and are marked stale. This clears by itself when the drive answers again.</translation>
    </message>
</context>
<context>
    <name>DriveDesk::MonitorFeature</name>
    <message>
        <source>&amp;Telegram Monitor</source>
        <translation>&amp;Telegram Monitor</translation>
    </message>
</context>
<context>
    <name>DriveDesk::NoticeBar</name>
    <message>
        <source>&amp;Cancel</source>
        <translation>&amp;Cancel</translation>
    </message>
    <message>
        <source>&amp;Reconnect</source>
        <translation>&amp;Reconnect</translation>
    </message>
    <message>
        <source>C&amp;onnect...</source>
        <translation>C&amp;onnect...</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ParameterBrowser</name>
    <message>
        <source>Search results for “%1”</source>
        <translation>Search results for “%1”</translation>
    </message>
    <message>
        <source>All parameters</source>
        <translation>All parameters</translation>
    </message>
    <message>
        <source>Not connected. Connect to a drive to see its parameters.</source>
        <translation>Not connected. Connect to a drive to see its parameters.</translation>
    </message>
    <message>
        <source>No parameter here matches the search and the filters.</source>
        <translation>No parameter here matches the search and the filters.</translation>
    </message>
    <message>
        <source>This group holds no parameters.</source>
        <translation>This group holds no parameters.</translation>
    </message>
    <message>
        <source>Favourite</source>
        <translation>Favourite</translation>
    </message>
    <message>
        <source>%1: none shown</source>
        <translation>%1: none shown</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n parameter(s) (filtered)</source>
        <translation>
            <numerusform>%1: %n parameter (filtered)</numerusform>
            <numerusform>%1: %n parameters (filtered)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1: %n parameter(s)</source>
        <translation>
            <numerusform>%1: %n parameter</numerusform>
            <numerusform>%1: %n parameters</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>DriveDesk::ParameterDelegate</name>
    <message>
        <source>this parameter cannot be changed now</source>
        <translation>this parameter cannot be changed now</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <comment>parameter, set</comment>
        <translation>%1, %2</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ParameterFileFeature</name>
    <message>
        <source>&amp;Open Parameter File...</source>
        <translation>&amp;Open Parameter File...</translation>
    </message>
    <message>
        <source>Show and edit a parameter file with no drive</source>
        <translation>Show and edit a parameter file with no drive</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Save</translation>
    </message>
    <message>
        <source>Save the changes of the parameter file shown</source>
        <translation>Save the changes of the parameter file shown</translation>
    </message>
    <message>
        <source>Save &amp;As...</source>
        <translation>Save &amp;As...</translation>
    </message>
    <message>
        <source>Save the parameter file shown under another name</source>
        <translation>Save the parameter file shown under another name</translation>
    </message>
    <message>
        <source>Open Parameter File</source>
        <translation>Open Parameter File</translation>
    </message>
    <message>
        <source>Could not open the file: %1</source>
        <translation>Could not open the file: %1</translation>
    </message>
    <message>
        <source>No drive is connected: the table shows the parameter file %1, and edits change the file only, once you save it (%2). Nothing is sent to a drive.</source>
        <translation>No drive is connected: the table shows the parameter file %1, and edits change the file only, once you save it (%2). Nothing is sent to a drive.</translation>
    </message>
    <message>
        <source>Save Parameter File</source>
        <translation>Save Parameter File</translation>
    </message>
    <message>
        <source>Could not save %1: %2. The file on disk is as it was.</source>
        <translation>Could not save %1: %2. The file on disk is as it was.</translation>
    </message>
    <message>
        <source>Saved %1.</source>
        <translation>Saved %1.</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Unsaved Changes</translation>
    </message>
    <message>
        <source>The parameter file %1 has changes that are not saved.</source>
        <translation>The parameter file %1 has changes that are not saved.</translation>
    </message>
    <message>
        <source>Save them before going on?</source>
        <translation>Save them before going on?</translation>
    </message>
    <message>
        <source>Save Parameter File As</source>
        <translation>Save Parameter File As</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ParameterModel</name>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message numerus="yes">
        <source>%1, %n parameter(s)</source>
        <translation>
            <numerusform>%1, %n parameter</numerusform>
            <numerusform>%1, %n parameters</numerusform>
        </translation>
    </message>
    <message>
        <source>?</source>
        <translation>?</translation>
    </message>
    <message>
        <source>Writing %1 ...</source>
        <translation>Writing %1 ...</translation>
    </message>
    <message>
        <source>Written: %1</source>
        <translation>Written: %1</translation>
    </message>
    <message>
        <source>Writing %1 failed: %2</source>
        <translation>Writing %1 failed: %2</translation>
    </message>
    <message>
        <source>Not read</source>
        <translation>Not read</translation>
    </message>
    <message>
        <source>Not read: %1</source>
        <translation>Not read: %1</translation>
    </message>
    <message>
        <source>raw %1 = %2h</source>
        <translation>raw %1 = %2h</translation>
    </message>
    <message>
        <source>read-only (read: %1)</source>
        <translation>read-only (read: %1)</translation>
    </message>
    <message>
        <source>read: %1, write: %2</source>
        <translation>read: %1, write: %2</translation>
    </message>
    <message>
        <source>Set 0, or the one value of a parameter that is not set-programmable</source>
        <translation>Set 0, or the one value of a parameter that is not set-programmable</translation>
    </message>
    <message>
        <source>Value / set 0</source>
        <translation>Value / set 0</translation>
    </message>
    <message>
        <source>Set %1</source>
        <translation>Set %1</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Minimum</source>
        <translation>Minimum</translation>
    </message>
    <message>
        <source>Maximum</source>
        <translation>Maximum</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Default</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unit</translation>
    </message>
    <message>
        <source>Access</source>
        <translation>Access</translation>
    </message>
    <message>
        <source>The drive runs with this set (active set, Fr.02)</source>
        <translation>The drive runs with this set (active set, Fr.02)</translation>
    </message>
    <message>
        <source>Value / set 0 (active)</source>
        <translation>Value / set 0 (active)</translation>
    </message>
    <message>
        <source>Set %1 (active)</source>
        <translation>Set %1 (active)</translation>
    </message>
    <message>
        <source>Last read %1; the drive is not answering</source>
        <translation>Last read %1; the drive is not answering</translation>
    </message>
    <message>
        <source>Changed in the file: %1; save to keep it</source>
        <translation>Changed in the file: %1; save to keep it</translation>
    </message>
    <message>
        <source>Whether the drive took %1 is unknown: %2</source>
        <translation>Whether the drive took %1 is unknown: %2</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PasswordDialog</name>
    <message>
        <source>Enter Password</source>
        <translation>Enter Password</translation>
    </message>
    <message>
        <source>0 to %1</source>
        <translation>0 to %1</translation>
    </message>
    <message>
        <source>Level in force:</source>
        <translation>Level in force:</translation>
    </message>
    <message>
        <source>&amp;Password:</source>
        <translation>&amp;Password:</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>not read yet</source>
        <translation>not read yet</translation>
    </message>
    <message>
        <source>Asking the drive ...</source>
        <translation>Asking the drive ...</translation>
    </message>
    <message>
        <source>Not accepted: %1</source>
        <translation>Not accepted: %1</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PlaintextComboBox</name>
    <message>
        <source>no text chosen</source>
        <translation>no text chosen</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PlantDock</name>
    <message>
        <source>Plant</source>
        <translation>Plant</translation>
    </message>
    <message>
        <source>No plant open. File &gt; New Plant or Open Plant.</source>
        <translation>No plant open. File &gt; New Plant or Open Plant.</translation>
    </message>
    <message>
        <source>Find</source>
        <translation>Find</translation>
    </message>
    <message>
        <source>Search every link for its drives and write the addresses found into the plant file</source>
        <translation>Search every link for its drives and write the addresses found into the plant file</translation>
    </message>
    <message>
        <source>Back Up All</source>
        <translation>Back Up All</translation>
    </message>
    <message>
        <source>Read every drive whole and save it to its file in the backup folder</source>
        <translation>Read every drive whole and save it to its file in the backup folder</translation>
    </message>
    <message>
        <source>Verify All</source>
        <translation>Verify All</translation>
    </message>
    <message>
        <source>Check every drive&apos;s settings against its file in the backup folder</source>
        <translation>Check every drive&apos;s settings against its file in the backup folder</translation>
    </message>
    <message>
        <source>Download All...</source>
        <translation>Download All...</translation>
    </message>
    <message>
        <source>Write each drive&apos;s file to the drive, after a last look at what each would get</source>
        <translation>Write each drive&apos;s file to the drive, after a last look at what each would get</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stop</translation>
    </message>
    <message>
        <source>Stop every link after the value on its way</source>
        <translation>Stop every link after the value on its way</translation>
    </message>
    <message>
        <source>Compare</source>
        <translation>Compare</translation>
    </message>
    <message>
        <source>Read the two selected drives afresh and compare them side by side</source>
        <translation>Read the two selected drives afresh and compare them side by side</translation>
    </message>
    <message>
        <source>Add Link...</source>
        <translation>Add Link...</translation>
    </message>
    <message>
        <source>Add a link to the plant file</source>
        <translation>Add a link to the plant file</translation>
    </message>
    <message>
        <source>Backup Folder...</source>
        <translation>Backup Folder...</translation>
    </message>
    <message>
        <source>Choose where the drives&apos; files are</source>
        <translation>Choose where the drives&apos; files are</translation>
    </message>
    <message>
        <source>Cannot make the folder %1.</source>
        <translation>Cannot make the folder %1.</translation>
    </message>
    <message>
        <source>The backup folder %1 does not exist: back the drives up first, or choose another folder.</source>
        <translation>The backup folder %1 does not exist: back the drives up first, or choose another folder.</translation>
    </message>
    <message>
        <source>The backup folder %1 does not exist.</source>
        <translation>The backup folder %1 does not exist.</translation>
    </message>
    <message>
        <source>A job is running on the plant shown; stop it first.</source>
        <translation>A job is running on the plant shown; stop it first.</translation>
    </message>
    <message>
        <source>Backup Folder</source>
        <translation>Backup Folder</translation>
    </message>
    <message>
        <source>Link %1 added to %2.</source>
        <translation>Link %1 added to %2.</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; &amp;mdash; %2 &amp;mdash; backups in %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; &amp;mdash; %2 &amp;mdash; backups in %3</translation>
    </message>
    <message>
        <source>Plant: %1</source>
        <translation>Plant: %1</translation>
    </message>
    <message>
        <source>%1 opens in the editor.</source>
        <translation>%1 opens in the editor.</translation>
    </message>
    <message>
        <source>Select two drives to compare.</source>
        <translation>Select two drives to compare.</translation>
    </message>
    <message>
        <source>Searching every link for its drives...</source>
        <translation>Searching every link for its drives...</translation>
    </message>
    <message>
        <source>Backing up every drive...</source>
        <translation>Backing up every drive...</translation>
    </message>
    <message>
        <source>Verifying every drive against its file...</source>
        <translation>Verifying every drive against its file...</translation>
    </message>
    <message>
        <source>Reading every drive to see what a download would write...</source>
        <translation>Reading every drive to see what a download would write...</translation>
    </message>
    <message>
        <source>Downloading to every drive...</source>
        <translation>Downloading to every drive...</translation>
    </message>
    <message>
        <source>Reading the two drives to compare...</source>
        <translation>Reading the two drives to compare...</translation>
    </message>
    <message>
        <source>downloaded or already equal</source>
        <translation>downloaded or already equal</translation>
    </message>
    <message>
        <source>Download All: Report</source>
        <translation>Download All: Report</translation>
    </message>
    <message>
        <source>No drive would be written to: each is already equal to its file, or cannot take it (see why).</source>
        <translation>No drive would be written to: each is already equal to its file, or cannot take it (see why).</translation>
    </message>
    <message numerus="yes">
        <source>%n drive(s) would be written to. Look at what each gets, then write.</source>
        <translation>
            <numerusform>%n drive would be written to. Look at what each gets, then write.</numerusform>
            <numerusform>%n drives would be written to. Look at what each gets, then write.</numerusform>
        </translation>
    </message>
    <message>
        <source>Download All: Last Look</source>
        <translation>Download All: Last Look</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>The drives could not be compared: %1</source>
        <translation>The drives could not be compared: %1</translation>
    </message>
    <message>
        <source>%1 and %2 read; the compare window shows them side by side.</source>
        <translation>%1 and %2 read; the compare window shows them side by side.</translation>
    </message>
    <message>
        <source>%1. The addresses found were written to %2.</source>
        <translation>%1. The addresses found were written to %2.</translation>
    </message>
    <message>
        <source>%1. The plant file was not changed: %2</source>
        <translation>%1. The plant file was not changed: %2</translation>
    </message>
    <message>
        <source>%1 as read at %2</source>
        <translation>%1 as read at %2</translation>
    </message>
    <message>
        <source>the editor is connected to this line (%1): disconnect it (Drive &gt; Disconnect) and start again; %2</source>
        <translation>the editor is connected to this line (%1): disconnect it (Drive &gt; Disconnect) and start again; %2</translation>
    </message>
    <message>
        <source>plant download of %1</source>
        <translation>plant download of %1</translation>
    </message>
    <message>
        <source>History...</source>
        <translation>History...</translation>
    </message>
    <message>
        <source>The backup folder&apos;s revisions: what changed when, two side by side, and a revision restored</source>
        <translation>The backup folder&apos;s revisions: what changed when, two side by side, and a revision restored</translation>
    </message>
    <message>
        <source>plant download of %1 at revision %2</source>
        <translation>plant download of %1 at revision %2</translation>
    </message>
    <message>
        <source>A job is running on the plant; restore once it is done.</source>
        <translation>A job is running on the plant; restore once it is done.</translation>
    </message>
    <message>
        <source>Reading every drive to see what restoring %1 would write...</source>
        <translation>Reading every drive to see what restoring %1 would write...</translation>
    </message>
    <message>
        <source>Restore to %1: Report</source>
        <translation>Restore to %1: Report</translation>
    </message>
    <message>
        <source>Restore to %1: Last Look</source>
        <translation>Restore to %1: Last Look</translation>
    </message>
    <message>
        <source>A job is running on the plant; start again once it is done.</source>
        <translation>A job is running on the plant; start again once it is done.</translation>
    </message>
    <message>
        <source>A job is running on the plant; compare once it is done.</source>
        <translation>A job is running on the plant; compare once it is done.</translation>
    </message>
    <message>
        <source>The plant has no drive %1.</source>
        <translation>The plant has no drive %1.</translation>
    </message>
    <message>
        <source>%1 and %2 side by side in the compare window.</source>
        <translation>%1 and %2 side by side in the compare window.</translation>
    </message>
    <message>
        <source>Commit to History</source>
        <translation>Commit to History</translation>
    </message>
    <message>
        <source>Make each Back Up All a revision of the backup folder&apos;s git repository, with what changed since the last one</source>
        <translation>Make each Back Up All a revision of the backup folder&apos;s git repository, with what changed since the last one</translation>
    </message>
    <message>
        <source>%1 Stopped: nothing committed.</source>
        <translation>%1 Stopped: nothing committed.</translation>
    </message>
    <message>
        <source>%1 Committing to the history...</source>
        <translation>%1 Committing to the history...</translation>
    </message>
    <message>
        <source>%1 Not committed: %2</source>
        <translation>%1 Not committed: %2</translation>
    </message>
    <message>
        <source>%1 No drive saved: nothing committed.</source>
        <translation>%1 No drive saved: nothing committed.</translation>
    </message>
    <message>
        <source>%1 No setting changed since the last revision: nothing committed.</source>
        <translation>%1 No setting changed since the last revision: nothing committed.</translation>
    </message>
    <message>
        <source>%1 Committed %2: %3</source>
        <translation>%1 Committed %2: %3</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PlantFeature</name>
    <message>
        <source>Plant files (*.json);;All files (*)</source>
        <translation>Plant files (*.json);;All files (*)</translation>
    </message>
    <message>
        <source>&amp;New Plant...</source>
        <translation>&amp;New Plant...</translation>
    </message>
    <message>
        <source>Name a machine and its first link, and save it as a plant file</source>
        <translation>Name a machine and its first link, and save it as a plant file</translation>
    </message>
    <message>
        <source>Open &amp;Plant...</source>
        <translation>Open &amp;Plant...</translation>
    </message>
    <message>
        <source>Show a plant file&apos;s links and drives in the plant view</source>
        <translation>Show a plant file&apos;s links and drives in the plant view</translation>
    </message>
    <message>
        <source>Open Plant</source>
        <translation>Open Plant</translation>
    </message>
    <message>
        <source>Open &amp;Recent Plant</source>
        <translation>Open &amp;Recent Plant</translation>
    </message>
    <message>
        <source>Pla&amp;nt View</source>
        <translation>Pla&amp;nt View</translation>
    </message>
    <message>
        <source>Could not open the plant: %1</source>
        <translation>Could not open the plant: %1</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Machine</translation>
    </message>
    <message>
        <source>Save New Plant</source>
        <translation>Save New Plant</translation>
    </message>
    <message>
        <source>Plant Hist&amp;ory...</source>
        <translation>Plant Hist&amp;ory...</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PlantHistoryWindow</name>
    <message>
        <source>Plant History - DriveDesk</source>
        <translation>Plant History - DriveDesk</translation>
    </message>
    <message>
        <source>every drive</source>
        <translation>every drive</translation>
    </message>
    <message>
        <source>Only the revisions that changed this drive (cabinet-5)</source>
        <translation>Only the revisions that changed this drive (cabinet-5)</translation>
    </message>
    <message>
        <source>&amp;Drive:</source>
        <translation>&amp;Drive:</translation>
    </message>
    <message>
        <source>every parameter</source>
        <translation>every parameter</translation>
    </message>
    <message>
        <source>Only the revisions that changed this parameter (op.28)</source>
        <translation>Only the revisions that changed this parameter (op.28)</translation>
    </message>
    <message>
        <source>&amp;Parameter:</source>
        <translation>&amp;Parameter:</translation>
    </message>
    <message>
        <source>Re&amp;fresh</source>
        <translation>Re&amp;fresh</translation>
    </message>
    <message>
        <source>Read the backup folder&apos;s revisions again</source>
        <translation>Read the backup folder&apos;s revisions again</translation>
    </message>
    <message>
        <source>Revision</source>
        <translation>Revision</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Time</translation>
    </message>
    <message>
        <source>Author</source>
        <translation>Author</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Message</translation>
    </message>
    <message>
        <source>Changes</source>
        <translation>Changes</translation>
    </message>
    <message>
        <source>What the revision selected changed against the one before</source>
        <translation>What the revision selected changed against the one before</translation>
    </message>
    <message>
        <source>Drive to co&amp;mpare:</source>
        <translation>Drive to co&amp;mpare:</translation>
    </message>
    <message>
        <source>&amp;Side by Side</source>
        <translation>&amp;Side by Side</translation>
    </message>
    <message>
        <source>The drive&apos;s file at the two revisions selected, or at the one selected and in the backup folder now, side by side in the compare window</source>
        <translation>The drive&apos;s file at the two revisions selected, or at the one selected and in the backup folder now, side by side in the compare window</translation>
    </message>
    <message>
        <source>Against the Dri&amp;ve</source>
        <translation>Against the Dri&amp;ve</translation>
    </message>
    <message>
        <source>The drive&apos;s file at the revision selected against the drive itself, read afresh, side by side in the compare window</source>
        <translation>The drive&apos;s file at the revision selected against the drive itself, read afresh, side by side in the compare window</translation>
    </message>
    <message>
        <source>&amp;Restore to This Revision...</source>
        <translation>&amp;Restore to This Revision...</translation>
    </message>
    <message>
        <source>Download the revision&apos;s files to the drives, after Download All&apos;s last look at what each would get</source>
        <translation>Download the revision&apos;s files to the drives, after Download All&apos;s last look at what each would get</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; &amp;mdash; revisions of the backups in %2</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; &amp;mdash; revisions of the backups in %2</translation>
    </message>
    <message>
        <source>Reading the revisions...</source>
        <translation>Reading the revisions...</translation>
    </message>
    <message>
        <source>No history to show: %1</source>
        <translation>No history to show: %1</translation>
    </message>
    <message>
        <source>%1 has no revisions yet: each backup committed with drivedesk-cli plant backup --commit becomes one.</source>
        <translation>%1 has no revisions yet: each backup committed with drivedesk-cli plant backup --commit becomes one.</translation>
    </message>
    <message>
        <source>No revision changed the drive or parameter the filter names.</source>
        <translation>No revision changed the drive or parameter the filter names.</translation>
    </message>
    <message>
        <source>Revisions: %1, newest first.</source>
        <translation>Revisions: %1, newest first.</translation>
    </message>
    <message>
        <source>Select one or two revisions and a drive to compare.</source>
        <translation>Select one or two revisions and a drive to compare.</translation>
    </message>
    <message>
        <source>Select one revision to restore.</source>
        <translation>Select one revision to restore.</translation>
    </message>
    <message>
        <source>Reading the revision&apos;s files...</source>
        <translation>Reading the revision&apos;s files...</translation>
    </message>
    <message>
        <source>The revision&apos;s files could not be read: %1</source>
        <translation>The revision&apos;s files could not be read: %1</translation>
    </message>
    <message>
        <source>%1 goes to Download All: look at what each drive would get, then write.</source>
        <translation>%1 goes to Download All: look at what each drive would get, then write.</translation>
    </message>
    <message>
        <source>%1 in the backup folder now</source>
        <translation>%1 in the backup folder now</translation>
    </message>
    <message>
        <source>%1 has no file there: %2</source>
        <translation>%1 has no file there: %2</translation>
    </message>
    <message>
        <source>Reading %1 to compare it with %2...</source>
        <translation>Reading %1 to compare it with %2...</translation>
    </message>
    <message>
        <source>%1 and %2 side by side in the compare window.</source>
        <translation>%1 and %2 side by side in the compare window.</translation>
    </message>
    <message>
        <source>%1 at %2 (%3)</source>
        <translation>%1 at %2 (%3)</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PlantLinkDialog</name>
    <message>
        <source>New Plant</source>
        <translation>New Plant</translation>
    </message>
    <message>
        <source>Add Link</source>
        <translation>Add Link</translation>
    </message>
    <message>
        <source>&amp;Machine:</source>
        <translation>&amp;Machine:</translation>
    </message>
    <message>
        <source>cabinet</source>
        <translation>cabinet</translation>
    </message>
    <message>
        <source>Names the link in reports and in the names of the drives&apos; files</source>
        <translation>Names the link in reports and in the names of the drives&apos; files</translation>
    </message>
    <message>
        <source>Link &amp;name:</source>
        <translation>Link &amp;name:</translation>
    </message>
    <message>
        <source>tcp:HOST:PORT, serial:DEVICE or sim</source>
        <translation>tcp:HOST:PORT, serial:DEVICE or sim</translation>
    </message>
    <message>
        <source>Connec&amp;t:</source>
        <translation>Connec&amp;t:</translation>
    </message>
    <message>
        <source>&amp;Protocol:</source>
        <translation>&amp;Protocol:</translation>
    </message>
    <message>
        <source>the protocol&apos;s default</source>
        <translation>the protocol&apos;s default</translation>
    </message>
    <message>
        <source>&amp;Baud rate:</source>
        <translation>&amp;Baud rate:</translation>
    </message>
    <message>
        <source>2, 5, 9; empty: search the bus</source>
        <translation>2, 5, 9; empty: search the bus</translation>
    </message>
    <message>
        <source>DIN66019(II): the drive addresses on the bus. HSP5 has one drive a line and no addresses.</source>
        <translation>DIN66019(II): the drive addresses on the bus. HSP5 has one drive a line and no addresses.</translation>
    </message>
    <message>
        <source>&amp;Addresses:</source>
        <translation>&amp;Addresses:</translation>
    </message>
    <message>
        <source>The baud rate &apos;%1&apos; is not a whole number.</source>
        <translation>The baud rate &apos;%1&apos; is not a whole number.</translation>
    </message>
    <message>
        <source>The address &apos;%1&apos; is not a whole number.</source>
        <translation>The address &apos;%1&apos; is not a whole number.</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PlantLinkRun</name>
    <message>
        <source>refused, nothing written: %1</source>
        <translation>refused, nothing written: %1</translation>
    </message>
    <message>
        <source>not everything was written; the report says what the drive holds</source>
        <translation>not everything was written; the report says what the drive holds</translation>
    </message>
    <message>
        <source>%1 does not exist</source>
        <translation>%1 does not exist</translation>
    </message>
    <message>
        <source>cannot connect: %1</source>
        <translation>cannot connect: %1</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>connecting</translation>
    </message>
    <message>
        <source>searching</source>
        <translation>searching</translation>
    </message>
    <message>
        <source>no drive answered</source>
        <translation>no drive answered</translation>
    </message>
    <message>
        <source>the search stopped: %1</source>
        <translation>the search stopped: %1</translation>
    </message>
    <message>
        <source>the search was stopped after %1 of %2 addresses</source>
        <translation>the search was stopped after %1 of %2 addresses</translation>
    </message>
    <message>
        <source>stopped before it was read</source>
        <translation>stopped before it was read</translation>
    </message>
    <message>
        <source>the connection was lost: %1</source>
        <translation>the connection was lost: %1</translation>
    </message>
    <message>
        <source>DIN66019 carries parameter values only: the drive has no parameter list to read or write; use din66019ii</source>
        <translation>DIN66019 carries parameter values only: the drive has no parameter list to read or write; use din66019ii</translation>
    </message>
    <message>
        <source>stopped before the drive was read whole; nothing saved</source>
        <translation>stopped before the drive was read whole; nothing saved</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PlantModel</name>
    <message>
        <source>not searched</source>
        <translation>not searched</translation>
    </message>
    <message>
        <source>answering</source>
        <translation>answering</translation>
    </message>
    <message>
        <source>unreachable</source>
        <translation>unreachable</translation>
    </message>
    <message>
        <source>, %1 baud</source>
        <translation>, %1 baud</translation>
    </message>
    <message>
        <source>%1 on %2%3</source>
        <translation>%1 on %2%3</translation>
    </message>
    <message>
        <source>Double-click to open the drive in the editor</source>
        <translation>Double-click to open the drive in the editor</translation>
    </message>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message numerus="yes">
        <source>differs from its file: %n setting(s)</source>
        <translation>
            <numerusform>differs from its file: %n setting</numerusform>
            <numerusform>differs from its file: %n settings</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>saved, %n parameter(s)</source>
        <translation>
            <numerusform>saved, %n parameter</numerusform>
            <numerusform>saved, %n parameters</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source> set %1</source>
        <translation> set %1</translation>
    </message>
    <message>
        <source>%1 %2%3: file %4, drive %5</source>
        <translation>%1 %2%3: file %4, drive %5</translation>
    </message>
    <message>
        <source>%1 %2: %3</source>
        <translation>%1 %2: %3</translation>
    </message>
    <message>
        <source>only in the file</source>
        <translation>only in the file</translation>
    </message>
    <message>
        <source>only on the drive</source>
        <translation>only on the drive</translation>
    </message>
    <message>
        <source>Link / drive</source>
        <translation>Link / drive</translation>
    </message>
    <message>
        <source>State</source>
        <translation>State</translation>
    </message>
    <message>
        <source>Identification</source>
        <translation>Identification</translation>
    </message>
    <message>
        <source>Last backup</source>
        <translation>Last backup</translation>
    </message>
    <message>
        <source>Last result</source>
        <translation>Last result</translation>
    </message>
    <message>
        <source>Progress</source>
        <translation>Progress</translation>
    </message>
    <message>
        <source>reading</source>
        <translation>reading</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PlantReportDialog</name>
    <message>
        <source>Drive</source>
        <translation>Drive</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Result</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>&amp;Write to the Drives</source>
        <translation>&amp;Write to the Drives</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PollingController</name>
    <message>
        <source>Polling stopped: the connection to the drive was lost</source>
        <translation>Polling stopped: the connection to the drive was lost</translation>
    </message>
    <message>
        <source>Polling stopped: disconnected from the drive</source>
        <translation>Polling stopped: disconnected from the drive</translation>
    </message>
    <message>
        <source>Nothing to poll: this drive has no readable values in group %1</source>
        <translation>Nothing to poll: this drive has no readable values in group %1</translation>
    </message>
    <message>
        <source>Polling: %1</source>
        <translation>Polling: %1</translation>
    </message>
    <message numerus="yes">
        <source>Polling: %n value(s) could not be read (first: %1: %2)</source>
        <translation>
            <numerusform>Polling: %n value could not be read (%1: %2)</numerusform>
            <numerusform>Polling: %n values could not be read (first: %1: %2)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>DriveDesk::PollingFeature</name>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>&amp;Poll Live Values</source>
        <translation>&amp;Poll Live Values</translation>
    </message>
    <message>
        <source>Read the run display (ru) again and again</source>
        <translation>Read the run display (ru) again and again</translation>
    </message>
    <message>
        <source>Every %1</source>
        <translation>Every %1</translation>
    </message>
    <message>
        <source>How often the live values are read</source>
        <translation>How often the live values are read</translation>
    </message>
    <message>
        <source>Polling &amp;Interval</source>
        <translation>Polling &amp;Interval</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PseudoTerminal</name>
    <message>
        <source>no path given for the pseudo-terminal link</source>
        <translation>no path given for the pseudo-terminal link</translation>
    </message>
    <message>
        <source>%1 already exists; choose another path or remove it</source>
        <translation>%1 already exists; choose another path or remove it</translation>
    </message>
    <message>
        <source>cannot create the link %1: %2</source>
        <translation>cannot create the link %1: %2</translation>
    </message>
    <message>
        <source>the pseudo-terminal was closed</source>
        <translation>the pseudo-terminal was closed</translation>
    </message>
</context>
<context>
    <name>DriveDesk::RecentConnections</name>
    <message>
        <source>%1, address %2</source>
        <translation>%1, address %2</translation>
    </message>
</context>
<context>
    <name>DriveDesk::SaveDriveFeature</name>
    <message>
        <source>Save &amp;Drive to File...</source>
        <translation>Save &amp;Drive to File...</translation>
    </message>
    <message>
        <source>Read the drive afresh and save it to a parameter file once every value was read; the window goes on with the drive</source>
        <translation>Read the drive afresh and save it to a parameter file once every value was read; the window goes on with the drive</translation>
    </message>
    <message>
        <source>Save Drive to File</source>
        <translation>Save Drive to File</translation>
    </message>
    <message>
        <source>Saving the drive to %1: %2</source>
        <translation>Saving the drive to %1: %2</translation>
    </message>
    <message>
        <source>Saving the drive to %1: reading the drive...</source>
        <translation>Saving the drive to %1: reading the drive...</translation>
    </message>
    <message>
        <source>Save Drive to File cancelled: nothing was saved to %1.</source>
        <translation>Save Drive to File cancelled: nothing was saved to %1.</translation>
    </message>
    <message>
        <source>The drive was not saved to %1: %2.</source>
        <translation>The drive was not saved to %1: %2.</translation>
    </message>
    <message>
        <source>Not read:</source>
        <translation>Not read:</translation>
    </message>
    <message numerus="yes">
        <source>... and %n more (Show Details...)</source>
        <translation>
            <numerusform>... and %n more (Show Details...)</numerusform>
            <numerusform>... and %n more (Show Details...)</numerusform>
        </translation>
    </message>
    <message>
        <source>Could not save %1: %2. The file on disk is as it was.</source>
        <translation>Could not save %1: %2. The file on disk is as it was.</translation>
    </message>
    <message numerus="yes">
        <source>Saved %n parameter(s) of the drive to %1.</source>
        <translation>
            <numerusform>Saved %n parameter of the drive to %1.</numerusform>
            <numerusform>Saved %n parameters of the drive to %1.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScaledSpinBox</name>
    <message>
        <source>%1 .. %2</source>
        <translation>%1 .. %2</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeChannelPanel</name>
    <message>
        <source>Channel</source>
        <translation>Channel</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Source</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unit</translation>
    </message>
    <message>
        <source>Colour of channel %1</source>
        <translation>Colour of channel %1</translation>
    </message>
    <message>
        <source>Show channel %1</source>
        <translation>Show channel %1</translation>
    </message>
    <message>
        <source>Own axis</source>
        <translation>Own axis</translation>
    </message>
    <message>
        <source>Give channel %1 a value axis of its own on the right</source>
        <translation>Give channel %1 a value axis of its own on the right</translation>
    </message>
    <message>
        <source>As the drive has it</source>
        <translation>As the drive has it</translation>
    </message>
    <message>
        <source>The parameter the drive delivers on channel %1</source>
        <translation>The parameter the drive delivers on channel %1</translation>
    </message>
    <message>
        <source>This drive&apos;s channels cannot be assigned from here: they are recorded as the drive has them.</source>
        <translation>This drive&apos;s channels cannot be assigned from here: they are recorded as the drive has them.</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Off</translation>
    </message>
    <message>
        <source>off</source>
        <translation>off</translation>
    </message>
    <message>
        <source>Channel %1 carries 16 bits: this parameter&apos;s values beyond -32768..32767 arrive cut to their low 16 bits.</source>
        <translation>Channel %1 carries 16 bits: this parameter&apos;s values beyond -32768..32767 arrive cut to their low 16 bits.</translation>
    </message>
    <message>
        <source>Set</source>
        <translation>Set</translation>
    </message>
    <message>
        <source>The parameter set the drive reads channel %1 from</source>
        <translation>The parameter set the drive reads channel %1 from</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeChannelsJob</name>
    <message>
        <source>This drive has no channel-assignment parameters (Sy.16 to Sy.23): its channels are recorded as it has them assigned.</source>
        <translation>This drive has no channel-assignment parameters (Sy.16 to Sy.23): its channels are recorded as it has them assigned.</translation>
    </message>
    <message>
        <source>Channel %1: %2 may not be recorded (the drive does not permit it as process data).</source>
        <translation>Channel %1: %2 may not be recorded (the drive does not permit it as process data).</translation>
    </message>
    <message>
        <source>Channel %1: choose at least one set.</source>
        <translation>Channel %1: choose at least one set.</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeChart</name>
    <message>
        <source>Time [s]</source>
        <translation>Time [s]</translation>
    </message>
    <message>
        <source>Could not write the image %1.</source>
        <translation>Could not write the image %1.</translation>
    </message>
    <message>
        <source>Could not write the PDF file %1.</source>
        <translation>Could not write the PDF file %1.</translation>
    </message>
    <message>
        <source>No file name was given.</source>
        <translation>No file name was given.</translation>
    </message>
    <message>
        <source>Cannot save %1: the folder %2 does not exist.</source>
        <translation>Cannot save %1: the folder %2 does not exist.</translation>
    </message>
    <message>
        <source>Cannot save %1: the folder %2 is not writable.</source>
        <translation>Cannot save %1: the folder %2 is not writable.</translation>
    </message>
    <message>
        <source>Cannot save %1: it is a folder.</source>
        <translation>Cannot save %1: it is a folder.</translation>
    </message>
    <message>
        <source>Cannot save %1: the file is read-only.</source>
        <translation>Cannot save %1: the file is read-only.</translation>
    </message>
    <message>
        <source>Wheel: zoom the time; Ctrl+wheel: zoom the values
Drag: move the time; Ctrl+drag: move the values
Shift+click: place cursor 1; Shift+right click: place cursor 2; drag a cursor to move it
+ and -: zoom the time (with Ctrl: the values); Left and Right: move the time; Up and Down: move the values
Home: the whole recording; End: follow the newest samples; A: fit the values; Space: freeze or go on; Esc: remove the cursors</source>
        <translation>Wheel: zoom the time; Ctrl+wheel: zoom the values
Drag: move the time; Ctrl+drag: move the values
Shift+click: place cursor 1; Shift+right click: place cursor 2; drag a cursor to move it
+ and -: zoom the time (with Ctrl: the values); Left and Right: move the time; Up and Down: move the values
Home: the whole recording; End: follow the newest samples; A: fit the values; Space: freeze or go on; Esc: remove the cursors</translation>
    </message>
    <message>
        <source>Trigger</source>
        <translation>Trigger</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeCursorTable</name>
    <message>
        <source>Cursors</source>
        <translation>Cursors</translation>
    </message>
    <message>
        <source>Cursor 1</source>
        <translation>Cursor 1</translation>
    </message>
    <message>
        <source>Cursor 2</source>
        <translation>Cursor 2</translation>
    </message>
    <message>
        <source>2 − 1</source>
        <comment>cursor 2 minus cursor 1</comment>
        <translation>2 − 1</translation>
    </message>
    <message>
        <source>Time [s]</source>
        <translation>Time [s]</translation>
    </message>
    <message>
        <source>%1 [%2]</source>
        <comment>channel title and unit</comment>
        <translation>%1 [%2]</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeDock</name>
    <message>
        <source>Scope</source>
        <translation>Scope</translation>
    </message>
    <message>
        <source>Record</source>
        <translation>Record</translation>
    </message>
    <message>
        <source>Record the drive&apos;s scope data; again to stop (F9)</source>
        <translation>Record the drive&apos;s scope data; again to stop (F9)</translation>
    </message>
    <message>
        <source>Pause View</source>
        <translation>Pause View</translation>
    </message>
    <message>
        <source>Hold the chart still; the recording goes on (Space in the chart)</source>
        <translation>Hold the chart still; the recording goes on (Space in the chart)</translation>
    </message>
    <message>
        <source>Roll</source>
        <translation>Roll</translation>
    </message>
    <message>
        <source>Follow the newest samples (End in the chart)</source>
        <translation>Follow the newest samples (End in the chart)</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>How many seconds the rolling view shows</source>
        <translation>How many seconds the rolling view shows</translation>
    </message>
    <message>
        <source>Whole</source>
        <translation>Whole</translation>
    </message>
    <message>
        <source>Show the whole recording (Home in the chart)</source>
        <translation>Show the whole recording (Home in the chart)</translation>
    </message>
    <message>
        <source>Auto-scale</source>
        <translation>Auto-scale</translation>
    </message>
    <message>
        <source>Fit the value axes to what is shown (A in the chart)</source>
        <translation>Fit the value axes to what is shown (A in the chart)</translation>
    </message>
    <message>
        <source>Max. rate</source>
        <translation>Max. rate</translation>
    </message>
    <message>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <source>as fast as the link</source>
        <translation>as fast as the link</translation>
    </message>
    <message>
        <source>Polls a second at most; 0: as fast as the link allows</source>
        <translation>Polls a second at most; 0: as fast as the link allows</translation>
    </message>
    <message>
        <source>Recording</source>
        <translation>Recording</translation>
    </message>
    <message>
        <source>Open Recording...</source>
        <translation>Open Recording...</translation>
    </message>
    <message>
        <source>Record to File...</source>
        <translation>Record to File...</translation>
    </message>
    <message>
        <source>Read Offline Records</source>
        <translation>Read Offline Records</translation>
    </message>
    <message>
        <source>Export All as CSV...</source>
        <translation>Export All as CSV...</translation>
    </message>
    <message>
        <source>Export Visible Range as CSV...</source>
        <translation>Export Visible Range as CSV...</translation>
    </message>
    <message>
        <source>Export Chart as PNG...</source>
        <translation>Export Chart as PNG...</translation>
    </message>
    <message>
        <source>Export Chart as PDF...</source>
        <translation>Export Chart as PDF...</translation>
    </message>
    <message>
        <source>Trigger</source>
        <translation>Trigger</translation>
    </message>
    <message>
        <source>Single Shot</source>
        <translation>Single Shot</translation>
    </message>
    <message>
        <source>Wait for the trigger, record one shot around it and stop</source>
        <translation>Wait for the trigger, record one shot around it and stop</translation>
    </message>
    <message>
        <source>Channel</source>
        <translation>Channel</translation>
    </message>
    <message>
        <source>rising</source>
        <translation>rising</translation>
    </message>
    <message>
        <source>falling</source>
        <translation>falling</translation>
    </message>
    <message>
        <source>Level</source>
        <translation>Level</translation>
    </message>
    <message>
        <source>Pre-trigger</source>
        <translation>Pre-trigger</translation>
    </message>
    <message>
        <source>The share of the shot before the trigger</source>
        <translation>The share of the shot before the trigger</translation>
    </message>
    <message>
        <source>Shot</source>
        <translation>Shot</translation>
    </message>
    <message>
        <source>How long the shot is</source>
        <translation>How long the shot is</translation>
    </message>
    <message>
        <source>Choose the sources and press Record (F9), or open a recording.</source>
        <translation>Choose the sources and press Record (F9), or open a recording.</translation>
    </message>
    <message>
        <source>Connect to a drive to record, or open a recording.</source>
        <translation>Connect to a drive to record, or open a recording.</translation>
    </message>
    <message numerus="yes">
        <source>%1: %Ln sample(s)</source>
        <translation>
            <numerusform>%1: %Ln sample</numerusform>
            <numerusform>%1: %Ln samples</numerusform>
        </translation>
    </message>
    <message>
        <source>DriveDesk scope recordings (*.%1)</source>
        <translation>DriveDesk scope recordings (*.%1)</translation>
    </message>
    <message>
        <source>Stop the recording before opening another.</source>
        <translation>Stop the recording before opening another.</translation>
    </message>
    <message>
        <source>Open Scope Recording</source>
        <translation>Open Scope Recording</translation>
    </message>
    <message>
        <source>Record to File</source>
        <translation>Record to File</translation>
    </message>
    <message>
        <source>Recordings stay in memory.</source>
        <translation>Recordings stay in memory.</translation>
    </message>
    <message>
        <source>The next recording also goes into %1.</source>
        <translation>The next recording also goes into %1.</translation>
    </message>
    <message>
        <source>There is nothing recorded to export.</source>
        <translation>There is nothing recorded to export.</translation>
    </message>
    <message>
        <source>Export Visible Range as CSV</source>
        <translation>Export Visible Range as CSV</translation>
    </message>
    <message>
        <source>Export All as CSV</source>
        <translation>Export All as CSV</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV files (*.csv)</translation>
    </message>
    <message>
        <source>Exported to %1.</source>
        <translation>Exported to %1.</translation>
    </message>
    <message>
        <source>Export Chart as PDF</source>
        <translation>Export Chart as PDF</translation>
    </message>
    <message>
        <source>Export Chart as PNG</source>
        <translation>Export Chart as PNG</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>PDF files (*.pdf)</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG images (*.png)</translation>
    </message>
    <message>
        <source>Assigning the channels...</source>
        <translation>Assigning the channels...</translation>
    </message>
    <message>
        <source>The channels could not be assigned: %1</source>
        <translation>The channels could not be assigned: %1</translation>
    </message>
    <message>
        <source>Recording...</source>
        <translation>Recording...</translation>
    </message>
    <message>
        <source>Triggered; recording the rest of the shot...</source>
        <translation>Triggered; recording the rest of the shot...</translation>
    </message>
    <message>
        <source>%1 samples, %2 Hz (average %3 Hz), %4 lost, %5 failed</source>
        <translation>%1 samples, %2 Hz (average %3 Hz), %4 lost, %5 failed</translation>
    </message>
    <message>
        <source>Waiting for the trigger; %1</source>
        <translation>Waiting for the trigger; %1</translation>
    </message>
    <message>
        <source>%1. Not recording to the file any more: %2</source>
        <translation>%1. Not recording to the file any more: %2</translation>
    </message>
    <message>
        <source>%1; into %2</source>
        <translation>%1; into %2</translation>
    </message>
    <message numerus="yes">
        <source>Recording stopped: %1. The %Ln sample(s) recorded are kept.</source>
        <translation>
            <numerusform>Recording stopped: %1. The %Ln sample recorded is kept.</numerusform>
            <numerusform>Recording stopped: %1. The %Ln samples recorded are kept.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Recorded %Ln sample(s) at %1 Hz on average; %2 lost, %3 failed.</source>
        <translation>
            <numerusform>Recorded %Ln sample at %1 Hz on average; %2 lost, %3 failed.</numerusform>
            <numerusform>Recorded %Ln samples at %1 Hz on average; %2 lost, %3 failed.</numerusform>
        </translation>
    </message>
    <message>
        <source>Waiting for the trigger...</source>
        <translation>Waiting for the trigger...</translation>
    </message>
    <message>
        <source>Reading the offline records...</source>
        <translation>Reading the offline records...</translation>
    </message>
    <message>
        <source>The connection went away.</source>
        <translation>The connection went away.</translation>
    </message>
    <message numerus="yes">
        <source>%n offline record(s) read</source>
        <translation>
            <numerusform>%n offline record read</numerusform>
            <numerusform>%n offline records read</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n with channel 3 or 4 beyond 16 bits, shown at the nearest 16-bit value</source>
        <translation>
            <numerusform>%n with channel 3 or 4 beyond 16 bits, shown at the nearest 16-bit value</numerusform>
            <numerusform>%n with channel 3 or 4 beyond 16 bits, shown at the nearest 16-bit value</numerusform>
        </translation>
    </message>
    <message>
        <source>Save Recording As...</source>
        <translation>Save Recording As...</translation>
    </message>
    <message>
        <source>There is nothing recorded to save.</source>
        <translation>There is nothing recorded to save.</translation>
    </message>
    <message>
        <source>Stop the recording before saving it, or use Record to File.</source>
        <translation>Stop the recording before saving it, or use Record to File.</translation>
    </message>
    <message>
        <source>Save Scope Recording</source>
        <translation>Save Scope Recording</translation>
    </message>
    <message>
        <source>Saved to %1.</source>
        <translation>Saved to %1.</translation>
    </message>
    <message>
        <source>Cannot save %1: %2</source>
        <translation>Cannot save %1: %2</translation>
    </message>
    <message numerus="yes">
        <source>Shot of %Ln sample(s) around the trigger.</source>
        <translation>
            <numerusform>Shot of %Ln sample around the trigger.</numerusform>
            <numerusform>Shot of %Ln samples around the trigger.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>%1 Saved to %2.</source>
        <translation>%1 Saved to %2.</translation>
    </message>
    <message>
        <source>The recording shown is not saved. The offline records replace it.</source>
        <translation>The recording shown is not saved. The offline records replace it.</translation>
    </message>
    <message>
        <source>The recording shown is not saved. The recording opened replaces it.</source>
        <translation>The recording shown is not saved. The recording opened replaces it.</translation>
    </message>
    <message>
        <source>Save it first?</source>
        <translation>Save it first?</translation>
    </message>
    <message>
        <source>&amp;Save...</source>
        <translation>&amp;Save...</translation>
    </message>
    <message>
        <source>The recording shown is not saved. A new recording replaces it.</source>
        <translation>The recording shown is not saved. A new recording replaces it.</translation>
    </message>
    <message>
        <source>Close DriveDesk</source>
        <translation>Close DriveDesk</translation>
    </message>
    <message>
        <source>The scope recording shown is not saved. Closing DriveDesk loses it.</source>
        <translation>The scope recording shown is not saved. Closing DriveDesk loses it.</translation>
    </message>
    <message>
        <source>A math channel cannot be computed: %1</source>
        <translation>A math channel cannot be computed: %1</translation>
    </message>
    <message>
        <source>Add Math Channel...</source>
        <translation>Add Math Channel...</translation>
    </message>
    <message>
        <source>Remove Math Channels</source>
        <translation>Remove Math Channels</translation>
    </message>
    <message>
        <source>Overlay Recording...</source>
        <translation>Overlay Recording...</translation>
    </message>
    <message>
        <source>Align Overlay at Trigger</source>
        <translation>Align Overlay at Trigger</translation>
    </message>
    <message>
        <source>Align Overlay at Start</source>
        <translation>Align Overlay at Start</translation>
    </message>
    <message>
        <source>Remove Overlay</source>
        <translation>Remove Overlay</translation>
    </message>
    <message>
        <source>Overlay Scope Recording</source>
        <translation>Overlay Scope Recording</translation>
    </message>
    <message>
        <source>Reading %1 to draw it over the recording...</source>
        <translation>Reading %1 to draw it over the recording...</translation>
    </message>
    <message>
        <source>The overlay is removed.</source>
        <translation>The overlay is removed.</translation>
    </message>
    <message numerus="yes">
        <source>%1 (%Ln sample(s)) drawn over the recording, aligned at its trigger.</source>
        <translation>
            <numerusform>%1 (%Ln sample) drawn over the recording, aligned at its trigger.</numerusform>
            <numerusform>%1 (%Ln samples) drawn over the recording, aligned at its trigger.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 (%Ln sample(s)) drawn over the recording, aligned at its start.</source>
        <translation>
            <numerusform>%1 (%Ln sample) drawn over the recording, aligned at its start.</numerusform>
            <numerusform>%1 (%Ln samples) drawn over the recording, aligned at its start.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 Not at the trigger: %2.</source>
        <translation>%1 Not at the trigger: %2.</translation>
    </message>
    <message>
        <source>Presets</source>
        <translation>Presets</translation>
    </message>
    <message>
        <source>Save the channels, trigger, roll and rate limit under a name, or load a set-up saved for this kind of drive</source>
        <translation>Save the channels, trigger, roll and rate limit under a name, or load a set-up saved for this kind of drive</translation>
    </message>
    <message>
        <source>Save Preset As...</source>
        <translation>Save Preset As...</translation>
    </message>
    <message>
        <source>Connect to a drive to load its presets</source>
        <translation>Connect to a drive to load its presets</translation>
    </message>
    <message>
        <source>%1 (plant)</source>
        <translation>%1 (plant)</translation>
    </message>
    <message>
        <source>No presets for this kind of drive</source>
        <translation>No presets for this kind of drive</translation>
    </message>
    <message>
        <source>Some presets cannot be read: %1</source>
        <translation>Some presets cannot be read: %1</translation>
    </message>
    <message>
        <source>Save Preset</source>
        <translation>Save Preset</translation>
    </message>
    <message>
        <source>Name of the preset for this kind of drive:</source>
        <translation>Name of the preset for this kind of drive:</translation>
    </message>
    <message>
        <source>Name of the preset, kept beside the plant %1:</source>
        <translation>Name of the preset, kept beside the plant %1:</translation>
    </message>
    <message>
        <source>Preset &apos;%1&apos; saved in %2.</source>
        <translation>Preset &apos;%1&apos; saved in %2.</translation>
    </message>
    <message>
        <source>A preset needs a name.</source>
        <translation>A preset needs a name.</translation>
    </message>
    <message>
        <source>Preset &apos;%1&apos; loaded.</source>
        <translation>Preset &apos;%1&apos; loaded.</translation>
    </message>
    <message>
        <source>Preset &apos;%1&apos; loaded, but: %2</source>
        <translation>Preset &apos;%1&apos; loaded, but: %2</translation>
    </message>
    <message>
        <source>Channel %1 (%2): %3</source>
        <translation>Channel %1 (%2): %3</translation>
    </message>
    <message>
        <source>A preset named &apos;%1&apos; is already saved in %2. Replace it?</source>
        <translation>A preset named &apos;%1&apos; is already saved in %2. Replace it?</translation>
    </message>
    <message>
        <source>&amp;Replace</source>
        <translation>&amp;Replace</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeFeature</name>
    <message>
        <source>&amp;Scope</source>
        <translation>&amp;Scope</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeMathDialog</name>
    <message>
        <source>Add Math Channel</source>
        <translation>Add Math Channel</translation>
    </message>
    <message>
        <source>Derivative (d/dt)</source>
        <translation>Derivative (d/dt)</translation>
    </message>
    <message>
        <source>Integral over time</source>
        <translation>Integral over time</translation>
    </message>
    <message>
        <source>Difference (first − second)</source>
        <translation>Difference (first − second)</translation>
    </message>
    <message>
        <source>Sum (first + second)</source>
        <translation>Sum (first + second)</translation>
    </message>
    <message>
        <source>Moving average</source>
        <translation>Moving average</translation>
    </message>
    <message>
        <source>&amp;Kind:</source>
        <translation>&amp;Kind:</translation>
    </message>
    <message>
        <source>&amp;Channel:</source>
        <translation>&amp;Channel:</translation>
    </message>
    <message>
        <source>&amp;Second channel:</source>
        <translation>&amp;Second channel:</translation>
    </message>
    <message>
        <source>samples</source>
        <translation>samples</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>&amp;Window:</source>
        <translation>&amp;Window:</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeMeasurementTable</name>
    <message>
        <source>Minimum</source>
        <translation>Minimum</translation>
    </message>
    <message>
        <source>Maximum</source>
        <translation>Maximum</translation>
    </message>
    <message>
        <source>Peak to peak</source>
        <translation>Peak to peak</translation>
    </message>
    <message>
        <source>Mean</source>
        <translation>Mean</translation>
    </message>
    <message>
        <source>RMS</source>
        <translation>RMS</translation>
    </message>
    <message>
        <source>Rise time</source>
        <translation>Rise time</translation>
    </message>
    <message>
        <source>Rise rate</source>
        <translation>Rise rate</translation>
    </message>
    <message>
        <source>Fall time</source>
        <translation>Fall time</translation>
    </message>
    <message>
        <source>Fall rate</source>
        <translation>Fall rate</translation>
    </message>
    <message>
        <source>Between the cursors, both included. Mean and RMS of the line through the samples; rise and fall between 10 % and 90 % of the span from minimum to maximum.</source>
        <translation>Between the cursors, both included. Mean and RMS of the line through the samples; rise and fall between 10 % and 90 % of the span from minimum to maximum.</translation>
    </message>
    <message>
        <source>%1 [%2]</source>
        <comment>channel title and unit</comment>
        <translation>%1 [%2]</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeOfflineJob</name>
    <message>
        <source>This connection cannot read offline records (service 21 needs DIN66019II).</source>
        <translation>This connection cannot read offline records (service 21 needs DIN66019II).</translation>
    </message>
    <message>
        <source>The drive holds no offline records.</source>
        <translation>The drive holds no offline records.</translation>
    </message>
    <message>
        <source>Record %1: %2</source>
        <translation>Record %1: %2</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeSpectrumView</name>
    <message>
        <source>Spectrum</source>
        <translation>Spectrum</translation>
    </message>
    <message>
        <source>&amp;Channel</source>
        <translation>&amp;Channel</translation>
    </message>
    <message>
        <source>&amp;Range</source>
        <translation>&amp;Range</translation>
    </message>
    <message>
        <source>the view</source>
        <translation>the view</translation>
    </message>
    <message>
        <source>between the cursors</source>
        <translation>between the cursors</translation>
    </message>
    <message>
        <source>&amp;Logarithmic amplitude</source>
        <translation>&amp;Logarithmic amplitude</translation>
    </message>
    <message>
        <source>Spectrum...</source>
        <translation>Spectrum...</translation>
    </message>
    <message>
        <source>The amplitude spectrum of a channel over the view or between the cursors (Ctrl+Shift+F)</source>
        <translation>The amplitude spectrum of a channel over the view or between the cursors (Ctrl+Shift+F)</translation>
    </message>
    <message>
        <source>No samples: record or open a recording.</source>
        <translation>No samples: record or open a recording.</translation>
    </message>
    <message>
        <source>Place both cursors on the chart for the range between them.</source>
        <translation>Place both cursors on the chart for the range between them.</translation>
    </message>
    <message>
        <source>No spectrum: %1</source>
        <translation>No spectrum: %1</translation>
    </message>
    <message numerus="yes">
        <source>%1: %Ln sample(s) from %2 s to %3 s, %4 points at %5 Hz, bins of %6 Hz</source>
        <translation>
            <numerusform>%1: %Ln sample from %2 s to %3 s, %4 points at %5 Hz, bins of %6 Hz</numerusform>
            <numerusform>%1: %Ln samples from %2 s to %3 s, %4 points at %5 Hz, bins of %6 Hz</numerusform>
        </translation>
    </message>
    <message>
        <source> (resampled to even spacing: the samples came unevenly)</source>
        <translation> (resampled to even spacing: the samples came unevenly)</translation>
    </message>
</context>
<context>
    <name>DriveDesk::SerialLink</name>
    <message>
        <source>no such serial device</source>
        <translation>no such serial device</translation>
    </message>
    <message>
        <source>permission denied (the port may be in use by another program, or the user may lack access to it)</source>
        <translation>permission denied (the port may be in use by another program, or the user may lack access to it)</translation>
    </message>
    <message>
        <source>the port is already open</source>
        <translation>the port is already open</translation>
    </message>
    <message>
        <source>the device is no longer available (adapter unplugged?)</source>
        <translation>the device is no longer available (adapter unplugged?)</translation>
    </message>
    <message>
        <source>reading from the port failed</source>
        <translation>reading from the port failed</translation>
    </message>
    <message>
        <source>writing to the port failed</source>
        <translation>writing to the port failed</translation>
    </message>
    <message>
        <source>the port does not support these settings</source>
        <translation>the port does not support these settings</translation>
    </message>
    <message>
        <source>the port is not open</source>
        <translation>the port is not open</translation>
    </message>
    <message>
        <source>timeout</source>
        <translation>timeout</translation>
    </message>
    <message>
        <source>unknown serial port error</source>
        <translation>unknown serial port error</translation>
    </message>
    <message>
        <source>no serial device given</source>
        <translation>no serial device given</translation>
    </message>
</context>
<context>
    <name>DriveDesk::SetsDialog</name>
    <message>
        <source>Write to Sets</source>
        <translation>Write to Sets</translation>
    </message>
    <message>
        <source>Write the value to these sets:</source>
        <translation>Write the value to these sets:</translation>
    </message>
    <message>
        <source>&amp;All</source>
        <translation>&amp;All</translation>
    </message>
    <message>
        <source>&amp;None</source>
        <translation>&amp;None</translation>
    </message>
    <message>
        <source>Copy Set</source>
        <translation>Copy Set</translation>
    </message>
    <message>
        <source>Copy every set-programmable value of one set into another:</source>
        <translation>Copy every set-programmable value of one set into another:</translation>
    </message>
    <message>
        <source>&amp;From:</source>
        <translation>&amp;From:</translation>
    </message>
    <message>
        <source>&amp;To:</source>
        <translation>&amp;To:</translation>
    </message>
    <message>
        <source>Set %1 (active)</source>
        <translation>Set %1 (active)</translation>
    </message>
    <message>
        <source>Set %1</source>
        <translation>Set %1</translation>
    </message>
</context>
<context>
    <name>DriveDesk::SetsFeature</name>
    <message>
        <source>Fr.02: the set the drive works with. Fr.09: the set that indirect addressing reaches.</source>
        <translation>Fr.02: the set the drive works with. Fr.09: the set that indirect addressing reaches.</translation>
    </message>
    <message>
        <source>?</source>
        <translation>?</translation>
    </message>
    <message>
        <source>Active set: %1</source>
        <translation>Active set: %1</translation>
    </message>
    <message>
        <source>Set pointer (Fr.09): %1</source>
        <translation>Set pointer (Fr.09): %1</translation>
    </message>
</context>
<context>
    <name>DriveDesk::SimulatedLink</name>
    <message>
        <source>parity error on a received character</source>
        <translation>parity error on a received character</translation>
    </message>
    <message>
        <source>simulated drive</source>
        <translation>simulated drive</translation>
    </message>
    <message numerus="yes">
        <source>simulated drive(s) %1</source>
        <translation>
            <numerusform>simulated drive %1</numerusform>
            <numerusform>simulated drives %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>DriveDesk::SimulatorServer</name>
    <message>
        <source>&quot;%1&quot; is not an IP address to listen on (give e.g. 127.0.0.1, localhost or *)</source>
        <translation>&quot;%1&quot; is not an IP address to listen on (give e.g. 127.0.0.1, localhost or *)</translation>
    </message>
    <message>
        <source>cannot listen on %1:%2: %3</source>
        <translation>cannot listen on %1:%2: %3</translation>
    </message>
</context>
<context>
    <name>DriveDesk::StartupOptions</name>
    <message>
        <source>unexpected argument &quot;%1&quot;</source>
        <translation>unexpected argument &quot;%1&quot;</translation>
    </message>
    <message>
        <source>--protocol, --address and --baud belong to --connect: give tcp:HOST:PORT, serial:DEVICE or sim</source>
        <translation>--protocol, --address and --baud belong to --connect: give tcp:HOST:PORT, serial:DEVICE or sim</translation>
    </message>
    <message>
        <source>--open shows a parameter file with no drive: leave out --connect, --protocol, --address and --baud</source>
        <translation>--open shows a parameter file with no drive: leave out --connect, --protocol, --address and --baud</translation>
    </message>
    <message>
        <source>Usage: drivedesk [--connect TARGET | --open FILE] [options]

The DriveDesk parameter editor. Without --connect or --open it opens the connection
dialog.

  --connect TARGET     tcp:HOST:PORT, serial:DEVICE or sim (the simulated drive)
  --open FILE          show and edit a parameter file with no drive
  --protocol NAME      hsp5 (default), din66019ii or din66019
  --address N          drive address on a DIN66019(II) bus, 0..239 (default 1)
  --baud N|auto        baud rate; auto (the default on a serial line) finds the rate
                       the drive answers at
  --language en|de     language of the window and of the drive&apos;s texts
  --journal PATH       the journal of the values written, instead of
                       ~/.local/share/DriveDesk/journal.sqlite
</source>
        <translation>Usage: drivedesk [--connect TARGET | --open FILE] [options]

The DriveDesk parameter editor. Without --connect or --open it opens the connection
dialog.

  --connect TARGET     tcp:HOST:PORT, serial:DEVICE or sim (the simulated drive)
  --open FILE          show and edit a parameter file with no drive
  --protocol NAME      hsp5 (default), din66019ii or din66019
  --address N          drive address on a DIN66019(II) bus, 0..239 (default 1)
  --baud N|auto        baud rate; auto (the default on a serial line) finds the rate
                       the drive answers at
  --language en|de     language of the window and of the drive&apos;s texts
  --journal PATH       the journal of the values written, instead of
                       ~/.local/share/DriveDesk/journal.sqlite
</translation>
    </message>
    <message>
        <source>--journal names a file: give a path</source>
        <translation>--journal names a file: give a path</translation>
    </message>
</context>
<context>
    <name>DriveDesk::TcpLink</name>
    <message>
        <source>no answer from the device server within %1 ms</source>
        <translation>no answer from the device server within %1 ms</translation>
    </message>
    <message>
        <source>no host or port given</source>
        <translation>no host or port given</translation>
    </message>
    <message>
        <source>writing failed (%1)</source>
        <translation>writing failed (%1)</translation>
    </message>
    <message>
        <source>the device server closed the connection</source>
        <translation>the device server closed the connection</translation>
    </message>
</context>
<context>
    <name>DriveDesk::TelegramMonitor</name>
    <message>
        <source>Telegram monitor</source>
        <translation>Telegram monitor</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Copy</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Hold new telegrams back and show them on resume</source>
        <translation>Hold new telegrams back and show them on resume</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Clear</translation>
    </message>
    <message>
        <source>Forget every telegram listed and held</source>
        <translation>Forget every telegram listed and held</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>Save…</translation>
    </message>
    <message>
        <source>Save the telegrams the filter shows to a CSV or text file</source>
        <translation>Save the telegrams the filter shows to a CSV or text file</translation>
    </message>
    <message>
        <source>Filter: meaning, hex bytes or characters</source>
        <translation>Filter: meaning, hex bytes or characters</translation>
    </message>
    <message>
        <source>Errors only</source>
        <translation>Errors only</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Resume</translation>
    </message>
    <message numerus="yes">
        <source>Saved %Ln telegram(s) to %1.</source>
        <translation>
            <numerusform>Saved %Ln telegram to %1.</numerusform>
            <numerusform>Saved %Ln telegrams to %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV files (*.csv)</translation>
    </message>
    <message>
        <source>Save telegrams</source>
        <translation>Save telegrams</translation>
    </message>
    <message>
        <source>Text files (*.txt)</source>
        <translation>Text files (*.txt)</translation>
    </message>
    <message numerus="yes">
        <source>%1 of %Ln telegram(s) shown</source>
        <translation>
            <numerusform>%1 of %Ln telegram shown</numerusform>
            <numerusform>%1 of %Ln telegrams shown</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%Ln telegram(s)</source>
        <translation>
            <numerusform>%Ln telegram</numerusform>
            <numerusform>%Ln telegrams</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%Ln older telegram(s) dropped: the monitor keeps the latest %1</source>
        <translation>
            <numerusform>%Ln older telegram dropped: the monitor keeps the latest %1</numerusform>
            <numerusform>%Ln older telegrams dropped: the monitor keeps the latest %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>paused: %Ln telegram(s) held, shown on resume</source>
        <translation>
            <numerusform>paused: %Ln telegram held, shown on resume</numerusform>
            <numerusform>paused: %Ln telegrams held, shown on resume</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>DriveDesk::TrafficModel</name>
    <message numerus="yes">
        <source>%n byte(s)</source>
        <translation>
            <numerusform>%n byte</numerusform>
            <numerusform>%n bytes</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>DriveDesk::UploadRun</name>
    <message>
        <source>no drive is connected</source>
        <translation>no drive is connected</translation>
    </message>
    <message>
        <source>the drive stopped answering during the read (no answer after every attempt)</source>
        <translation>the drive stopped answering during the read (no answer after every attempt)</translation>
    </message>
    <message>
        <source>the read ended without a result</source>
        <translation>the read ended without a result</translation>
    </message>
    <message>
        <source>the connection was closed</source>
        <translation>the connection was closed</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ValueEdits</name>
    <message>
        <source>the connection to the drive was closed</source>
        <translation>the connection to the drive was closed</translation>
    </message>
</context>
<context>
    <name>DriveDesk::WriteJournal</name>
    <message>
        <source>&amp;Journal Every Write</source>
        <translation>&amp;Journal Every Write</translation>
    </message>
    <message>
        <source>Record every value written to the drive, with the value before and after, in the journal %1</source>
        <translation>Record every value written to the drive, with the value before and after, in the journal %1</translation>
    </message>
    <message>
        <source>Every value written is journaled.</source>
        <translation>Every value written is journaled.</translation>
    </message>
    <message>
        <source>Values written are not journaled.</source>
        <translation>Values written are not journaled.</translation>
    </message>
    <message>
        <source>edit</source>
        <translation>edit</translation>
    </message>
    <message>
        <source>%1 (Drive &gt; Journal Every Write off writes without it)</source>
        <translation>%1 (Drive &gt; Journal Every Write off writes without it)</translation>
    </message>
</context>
<context>
    <name>DriveIdentity</name>
    <message>
        <source>Identification</source>
        <translation>Identification</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>not read: %1</source>
        <translation>not read: %1</translation>
    </message>
    <message>
        <source>no value</source>
        <translation>no value</translation>
    </message>
    <message>
        <source>Type %1</source>
        <translation>Type %1</translation>
    </message>
    <message>
        <source>Type %1, software %2</source>
        <translation>Type %1, software %2</translation>
    </message>
    <message>
        <source>Type %1, software %2, serial number %3</source>
        <translation>Type %1, software %2, serial number %3</translation>
    </message>
</context>
<context>
    <name>EditCheck</name>
    <message>
        <source>%1 is read-only</source>
        <translation>%1 is read-only</translation>
    </message>
    <message>
        <source>%1 needs password level %2 (in force: %3)</source>
        <translation>%1 needs password level %2 (in force: %3)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: no set chosen</source>
        <translation>%1: no set chosen</translation>
    </message>
</context>
<context>
    <name>EditJournal</name>
    <message>
        <source>not sent: %1</source>
        <translation>not sent: %1</translation>
    </message>
    <message>
        <source>the journal cannot record it: %1</source>
        <translation>the journal cannot record it: %1</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
</context>
<context>
    <name>EditText</name>
    <message>
        <source>%1 not reset%2: %3</source>
        <translation>%1 not reset%2: %3</translation>
    </message>
    <message>
        <source>%1 = %2 not written%3: %4</source>
        <translation>%1 = %2 not written%3: %4</translation>
    </message>
    <message>
        <source>%1 reset to its default%2</source>
        <translation>%1 reset to its default%2</translation>
    </message>
    <message>
        <source>%1 = %2 written%3</source>
        <translation>%1 = %2 written%3</translation>
    </message>
    <message>
        <source>; not%1: %2</source>
        <translation>; not%1: %2</translation>
    </message>
    <message>
        <source>; reading it back failed: %1</source>
        <translation>; reading it back failed: %1</translation>
    </message>
    <message>
        <source>the drive holds %1%2</source>
        <translation>the drive holds %1%2</translation>
    </message>
    <message>
        <source>%1 reset%2 unknown: no answer, so whether the drive took it is unknown (%3)</source>
        <translation>%1 reset%2 unknown: no answer, so whether the drive took it is unknown (%3)</translation>
    </message>
    <message>
        <source>%1 = %2%3 unknown: no answer, so whether the drive took it is unknown (%4)</source>
        <translation>%1 = %2%3 unknown: no answer, so whether the drive took it is unknown (%4)</translation>
    </message>
    <message>
        <source>; its answer was lost, and reading it back showed it taken</source>
        <translation>; its answer was lost, and reading it back showed it taken</translation>
    </message>
    <message>
        <source>; whether the drive took it%1 is unknown: no answer (%2)</source>
        <translation>; whether the drive took it%1 is unknown: no answer (%2)</translation>
    </message>
</context>
<context>
    <name>FindDrivesJob</name>
    <message>
        <source>inverter identifier %1</source>
        <translation>inverter identifier %1</translation>
    </message>
    <message>
        <source>software %1</source>
        <translation>software %1</translation>
    </message>
    <message>
        <source>serial number %1</source>
        <translation>serial number %1</translation>
    </message>
    <message>
        <source>, </source>
        <translation>, </translation>
    </message>
    <message>
        <source>the addresses %1..%2 hold no drive address (drives are 0..239)</source>
        <translation>the addresses %1..%2 hold no drive address (drives are 0..239)</translation>
    </message>
    <message>
        <source>drive %1: %2</source>
        <translation>drive %1: %2</translation>
    </message>
    <message>
        <source>drive %1 answered</source>
        <translation>drive %1 answered</translation>
    </message>
    <message>
        <source>no drive at %1</source>
        <translation>no drive at %1</translation>
    </message>
</context>
<context>
    <name>Git</name>
    <message>
        <source>git cannot be run (%1): install git</source>
        <translation>git cannot be run (%1): install git</translation>
    </message>
    <message>
        <source>git %1 failed with exit code %2</source>
        <translation>git %1 failed with exit code %2</translation>
    </message>
    <message>
        <source>git %1 failed: %2</source>
        <translation>git %1 failed: %2</translation>
    </message>
</context>
<context>
    <name>GroupProperties</name>
    <message>
        <source>password level: %1</source>
        <translation>password level: %1</translation>
    </message>
    <message>
        <source>visible on the display</source>
        <translation>visible on the display</translation>
    </message>
    <message>
        <source>visible in COMBIVIS</source>
        <translation>visible in COMBIVIS</translation>
    </message>
    <message>
        <source>free bit %1 set</source>
        <translation>free bit %1 set</translation>
    </message>
</context>
<context>
    <name>Journal</name>
    <message>
        <source>cannot open the journal %1: Qt&apos;s SQLite driver (QSQLITE) is missing</source>
        <translation>cannot open the journal %1: Qt&apos;s SQLite driver (QSQLITE) is missing</translation>
    </message>
    <message>
        <source>cannot write the journal %1: SQLite cannot keep a write-ahead log there (journal mode %2)</source>
        <translation>cannot write the journal %1: SQLite cannot keep a write-ahead log there (journal mode %2)</translation>
    </message>
    <message>
        <source>the journal %1 is not open for writing</source>
        <translation>the journal %1 is not open for writing</translation>
    </message>
    <message>
        <source>the journal %1 has no entry %2</source>
        <translation>the journal %1 has no entry %2</translation>
    </message>
    <message>
        <source>the journal %1 is not open</source>
        <translation>the journal %1 is not open</translation>
    </message>
</context>
<context>
    <name>JournalEntryText</name>
    <message>
        <source>written</source>
        <translation>written</translation>
    </message>
    <message>
        <source>refused</source>
        <translation>refused</translation>
    </message>
    <message>
        <source>refused: %1</source>
        <translation>refused: %1</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unknown</translation>
    </message>
    <message>
        <source>unknown: %1</source>
        <translation>unknown: %1</translation>
    </message>
    <message>
        <source>%1 since %2 by %3</source>
        <translation>%1 since %2 by %3</translation>
    </message>
    <message>
        <source>%1 since %2 by %3, was %4</source>
        <translation>%1 since %2 by %3, was %4</translation>
    </message>
</context>
<context>
    <name>JournalFilterText</name>
    <message>
        <source>&apos;%1&apos; names no drive: give its serial number, its link (serial:/dev/ttyUSB0) or LINK@ADDRESS (serial:/dev/ttyUSB0@3)</source>
        <translation>&apos;%1&apos; names no drive: give its serial number, its link (serial:/dev/ttyUSB0) or LINK@ADDRESS (serial:/dev/ttyUSB0@3)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is no parameter: give its id like op.28 or its address like 0x0A1C</source>
        <translation>&apos;%1&apos; is no parameter: give its id like op.28 or its address like 0x0A1C</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is no time: use a date like 2026-11-24 or a date and time like 2026-11-24T10:42 (local time)</source>
        <translation>&apos;%1&apos; is no time: use a date like 2026-11-24 or a date and time like 2026-11-24T10:42 (local time)</translation>
    </message>
</context>
<context>
    <name>JournalFormat</name>
    <message>
        <source>active</source>
        <translation>active</translation>
    </message>
    <message>
        <source>(password)</source>
        <translation>(password)</translation>
    </message>
    <message>
        <source>no entries</source>
        <translation>no entries</translation>
    </message>
    <message>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Time</translation>
    </message>
    <message>
        <source>User</source>
        <translation>User</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>Drive</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Set</source>
        <translation>Set</translation>
    </message>
    <message>
        <source>Before</source>
        <translation>Before</translation>
    </message>
    <message>
        <source>Written</source>
        <translation>Written</translation>
    </message>
    <message>
        <source>Read back</source>
        <translation>Read back</translation>
    </message>
    <message>
        <source>Outcome</source>
        <translation>Outcome</translation>
    </message>
    <message>
        <source>Job</source>
        <translation>Job</translation>
    </message>
</context>
<context>
    <name>JournalProblem</name>
    <message>
        <source>cannot write the journal %1: the folder %2 cannot be made</source>
        <translation>cannot write the journal %1: the folder %2 cannot be made</translation>
    </message>
    <message>
        <source>cannot write the journal %1: it is no file</source>
        <translation>cannot write the journal %1: it is no file</translation>
    </message>
    <message>
        <source>cannot write the journal %1: the file is read-only</source>
        <translation>cannot write the journal %1: the file is read-only</translation>
    </message>
    <message>
        <source>cannot write the journal %1: the folder %2 is read-only (the journal keeps %3-wal and %3-shm beside it)</source>
        <translation>cannot write the journal %1: the folder %2 is read-only (the journal keeps %3-wal and %3-shm beside it)</translation>
    </message>
    <message>
        <source>cannot write the journal %1: the disk is full</source>
        <translation>cannot write the journal %1: the disk is full</translation>
    </message>
    <message>
        <source>there is no journal %1</source>
        <translation>there is no journal %1</translation>
    </message>
    <message>
        <source>cannot read the journal %1: it is no file</source>
        <translation>cannot read the journal %1: it is no file</translation>
    </message>
    <message>
        <source>cannot read the journal %1: permission denied</source>
        <translation>cannot read the journal %1: permission denied</translation>
    </message>
    <message>
        <source>the journal %1 is locked by another program: waited %2 ms for it</source>
        <translation>the journal %1 is locked by another program: waited %2 ms for it</translation>
    </message>
    <message>
        <source>cannot write the journal %1: it is read-only (%2)</source>
        <translation>cannot write the journal %1: it is read-only (%2)</translation>
    </message>
    <message>
        <source>cannot write the journal %1: the disk failed or is full (%2)</source>
        <translation>cannot write the journal %1: the disk failed or is full (%2)</translation>
    </message>
    <message>
        <source>cannot open the journal %1 (%2)</source>
        <translation>cannot open the journal %1 (%2)</translation>
    </message>
    <message>
        <source>the journal %1: %2</source>
        <translation>the journal %1: %2</translation>
    </message>
    <message>
        <source>%1 is no DriveDesk journal: it is damaged or not a journal at all</source>
        <translation>%1 is no DriveDesk journal: it is damaged or not a journal at all</translation>
    </message>
    <message>
        <source>the journal %1 was made by a newer DriveDesk (journal version %2; this one knows up to %3): it is not written</source>
        <translation>the journal %1 was made by a newer DriveDesk (journal version %2; this one knows up to %3): it is not written</translation>
    </message>
</context>
<context>
    <name>JournalRevert</name>
    <message>
        <source>revert</source>
        <translation>revert</translation>
    </message>
    <message>
        <source>revert of entry %1</source>
        <translation>revert of entry %1</translation>
    </message>
    <message>
        <source>revert of entries %1..%2</source>
        <translation>revert of entries %1..%2</translation>
    </message>
    <message>
        <source>entry %1: the journal has no such entry</source>
        <translation>entry %1: the journal has no such entry</translation>
    </message>
    <message>
        <source>entry %1 (%2)</source>
        <translation>entry %1 (%2)</translation>
    </message>
    <message>
        <source>%1 was written to another drive (%2), not the one connected (%3)</source>
        <translation>%1 was written to another drive (%2), not the one connected (%3)</translation>
    </message>
    <message>
        <source>%1 is a password entered: the journal keeps no value of it, so it cannot be reverted</source>
        <translation>%1 is a password entered: the journal keeps no value of it, so it cannot be reverted</translation>
    </message>
    <message>
        <source>%1: the drive has no such parameter</source>
        <translation>%1: the drive has no such parameter</translation>
    </message>
    <message>
        <source>%1: the value before was not read, so there is none to write back</source>
        <translation>%1: the value before was not read, so there is none to write back</translation>
    </message>
    <message>
        <source>%1 was written to the active set, and the journal does not say which set that was</source>
        <translation>%1 was written to the active set, and the journal does not say which set that was</translation>
    </message>
    <message>
        <source>&apos;%1&apos; names no entry: give an entry&apos;s number (12) or a range (12..15)</source>
        <translation>&apos;%1&apos; names no entry: give an entry&apos;s number (12) or a range (12..15)</translation>
    </message>
    <message>
        <source>the value before entry %1</source>
        <translation>the value before entry %1</translation>
    </message>
    <message>
        <source>the values before the entries</source>
        <translation>the values before the entries</translation>
    </message>
    <message>
        <source>the values before entries %1..%2</source>
        <translation>the values before entries %1..%2</translation>
    </message>
</context>
<context>
    <name>MetadataCache</name>
    <message>
        <source>not JSON (%1 at byte %2)</source>
        <translation>not JSON (%1 at byte %2)</translation>
    </message>
    <message>
        <source>not a DriveDesk metadata cache file</source>
        <translation>not a DriveDesk metadata cache file</translation>
    </message>
    <message>
        <source>cache version %1, this DriveDesk reads version %2</source>
        <translation>cache version %1, this DriveDesk reads version %2</translation>
    </message>
    <message>
        <source>it holds another kind of drive</source>
        <translation>it holds another kind of drive</translation>
    </message>
    <message>
        <source>it has no languages</source>
        <translation>it has no languages</translation>
    </message>
    <message>
        <source>language %1 holds the texts of language %2</source>
        <translation>language %1 holds the texts of language %2</translation>
    </message>
    <message>
        <source>metadata cache file &apos;%1&apos; ignored and removed: %2</source>
        <translation>metadata cache file &apos;%1&apos; ignored and removed: %2</translation>
    </message>
    <message>
        <source>cannot create the metadata cache folder &apos;%1&apos;</source>
        <translation>cannot create the metadata cache folder &apos;%1&apos;</translation>
    </message>
    <message>
        <source>cannot remove &apos;%1&apos;</source>
        <translation>cannot remove &apos;%1&apos;</translation>
    </message>
    <message>
        <source>cannot write the metadata cache: %1</source>
        <translation>cannot write the metadata cache: %1</translation>
    </message>
</context>
<context>
    <name>MetadataMatch</name>
    <message>
        <source>divisor %1, multiplier %2, offset %3, flags %4h</source>
        <translation>divisor %1, multiplier %2, offset %3, flags %4h</translation>
    </message>
    <message>
        <source>name</source>
        <translation>name</translation>
    </message>
    <message>
        <source>properties 1</source>
        <translation>properties 1</translation>
    </message>
    <message>
        <source>properties 2</source>
        <translation>properties 2</translation>
    </message>
    <message>
        <source>display scaling</source>
        <translation>display scaling</translation>
    </message>
    <message>
        <source>lower limit</source>
        <translation>lower limit</translation>
    </message>
    <message>
        <source>upper limit</source>
        <translation>upper limit</translation>
    </message>
    <message>
        <source>id</source>
        <translation>id</translation>
    </message>
</context>
<context>
    <name>ParameterComparison</name>
    <message>
        <source>?</source>
        <translation>?</translation>
    </message>
</context>
<context>
    <name>ParameterCsv</name>
    <message>
        <source>id</source>
        <translation>id</translation>
    </message>
    <message>
        <source>name</source>
        <translation>name</translation>
    </message>
    <message>
        <source>unit</source>
        <translation>unit</translation>
    </message>
    <message>
        <source>set %1</source>
        <translation>set %1</translation>
    </message>
</context>
<context>
    <name>ParameterDocument</name>
    <message>
        <source>expected an object</source>
        <translation>expected an object</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>missing</translation>
    </message>
    <message>
        <source>expected an integer</source>
        <translation>expected an integer</translation>
    </message>
    <message>
        <source>%1 is outside %2..%3</source>
        <translation>%1 is outside %2..%3</translation>
    </message>
    <message>
        <source>expected a string</source>
        <translation>expected a string</translation>
    </message>
    <message>
        <source>expected true or false</source>
        <translation>expected true or false</translation>
    </message>
    <message>
        <source>expected an array</source>
        <translation>expected an array</translation>
    </message>
    <message>
        <source>unknown field</source>
        <translation>unknown field</translation>
    </message>
    <message>
        <source>&apos;%1&apos; names %2, not the address %3</source>
        <translation>&apos;%1&apos; names %2, not the address %3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; does not agree with scaling.flags (unit &apos;%2&apos;)</source>
        <translation>&apos;%1&apos; does not agree with scaling.flags (unit &apos;%2&apos;)</translation>
    </message>
    <message numerus="yes">
        <source>%1 does not agree with scaling.flags (%n decimals)</source>
        <translation>
            <numerusform>%1 does not agree with scaling.flags (%n decimal)</numerusform>
            <numerusform>%1 does not agree with scaling.flags (%n decimals)</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 does not agree with properties1 bit 11</source>
        <translation>%1 does not agree with properties1 bit 11</translation>
    </message>
    <message>
        <source>%1 does not agree with properties2 bit 3</source>
        <translation>%1 does not agree with properties2 bit 3</translation>
    </message>
    <message numerus="yes">
        <source>%n entries; a set-programmable parameter has one for each of the 8 sets</source>
        <translation>
            <numerusform>%n entry; a set-programmable parameter has one for each of the 8 sets</numerusform>
            <numerusform>%n entries; a set-programmable parameter has one for each of the 8 sets</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n entries; expected 1 (or 8, one for each set)</source>
        <translation>
            <numerusform>%n entry; expected 1 (or 8, one for each set)</numerusform>
            <numerusform>%n entries; expected 1 (or 8, one for each set)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1, but plaintextDefinitions has %n entries</source>
        <translation>
            <numerusform>%1, but plaintextDefinitions has %n entry</numerusform>
            <numerusform>%1, but plaintextDefinitions has %n entries</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 is not in group %2 (%3)</source>
        <translation>%1 is not in group %2 (%3)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not one Latin-1 character</source>
        <translation>&apos;%1&apos; is not one Latin-1 character</translation>
    </message>
    <message>
        <source>&apos;%1&apos; appears twice</source>
        <translation>&apos;%1&apos; appears twice</translation>
    </message>
    <message>
        <source>%1 is also the address of group %2</source>
        <translation>%1 is also the address of group %2</translation>
    </message>
    <message>
        <source>%1 appears twice</source>
        <translation>%1 appears twice</translation>
    </message>
    <message>
        <source>not valid JSON: %1 at line %2, column %3</source>
        <translation>not valid JSON: %1 at line %2, column %3</translation>
    </message>
    <message>
        <source>not a DriveDesk parameter file: the document is not a JSON object</source>
        <translation>not a DriveDesk parameter file: the document is not a JSON object</translation>
    </message>
    <message>
        <source>not a DriveDesk parameter file: format is %1, expected &apos;%2&apos;</source>
        <translation>not a DriveDesk parameter file: format is %1, expected &apos;%2&apos;</translation>
    </message>
    <message>
        <source>missing or not a string</source>
        <translation>missing or not a string</translation>
    </message>
    <message>
        <source>version: missing or not a number</source>
        <translation>version: missing or not a number</translation>
    </message>
    <message>
        <source>version: %1 is not supported (this DriveDesk reads version %2)</source>
        <translation>version: %1 is not supported (this DriveDesk reads version %2)</translation>
    </message>
    <message>
        <source>version: %1 is a newer format than this DriveDesk reads (version %2); a newer DriveDesk reads it</source>
        <translation>version: %1 is a newer format than this DriveDesk reads (version %2); a newer DriveDesk reads it</translation>
    </message>
    <message>
        <source>%1 is below min %2</source>
        <translation>%1 is below min %2</translation>
    </message>
    <message>
        <source>%1 is outside min..max (%2..%3), and properties1 says default and limits are constant</source>
        <translation>%1 is outside min..max (%2..%3), and properties1 says default and limits are constant</translation>
    </message>
    <message>
        <source>&apos;%1&apos; cannot stand in a parameter id: %2</source>
        <translation>&apos;%1&apos; cannot stand in a parameter id: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; names another address</source>
        <translation>&apos;%1&apos; names another address</translation>
    </message>
    <message>
        <source>%1 (line %2, column %3)</source>
        <translation>%1 (line %2, column %3)</translation>
    </message>
    <message>
        <source>%1: appears twice in one object (line %2, column %3)</source>
        <translation>%1: appears twice in one object (line %2, column %3)</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <comment>a parameter id, then a set or a field of it</comment>
        <translation>%1, %2</translation>
    </message>
</context>
<context>
    <name>ParameterFormat</name>
    <message>
        <source>%1 is outside the limits %2 .. %3</source>
        <translation>%1 is outside the limits %2 .. %3</translation>
    </message>
    <message>
        <source>no value given</source>
        <translation>no value given</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a whole number</source>
        <translation>&apos;%1&apos; is not a whole number</translation>
    </message>
    <message>
        <source>&apos;%1&apos; does not fit in 32 bits</source>
        <translation>&apos;%1&apos; does not fit in 32 bits</translation>
    </message>
    <message>
        <source>%1 cannot be set exactly: the nearest value this parameter can hold is %2</source>
        <translation>%1 cannot be set exactly: the nearest value this parameter can hold is %2</translation>
    </message>
</context>
<context>
    <name>ParameterId</name>
    <message>
        <source>no parameter given</source>
        <translation>no parameter given</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: address above FFFFh</source>
        <translation>&apos;%1&apos;: address above FFFFh</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: the group id is ambiguous (&apos;%2&apos; or &apos;%3&apos;); write it with its case</source>
        <translation>&apos;%1&apos;: the group id is ambiguous (&apos;%2&apos; or &apos;%3&apos;); write it with its case</translation>
    </message>
    <message>
        <source>no group &apos;%1&apos; on this drive</source>
        <translation>no group &apos;%1&apos; on this drive</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: parameter number above 255</source>
        <translation>&apos;%1&apos;: parameter number above 255</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: parameter number above %2 in group %3</source>
        <translation>&apos;%1&apos;: parameter number above %2 in group %3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a parameter id: write it as group.number (ru.03, ru03) or as a hexadecimal address (0203h, 0x0203)</source>
        <translation>&apos;%1&apos; is not a parameter id: write it as group.number (ru.03, ru03) or as a hexadecimal address (0203h, 0x0203)</translation>
    </message>
</context>
<context>
    <name>ParameterList</name>
    <message>
        <source>not part of a parameter list</source>
        <translation>not part of a parameter list</translation>
    </message>
    <message>
        <source>read-only</source>
        <translation>read-only</translation>
    </message>
    <message>
        <source>read-only for parameter lists</source>
        <translation>read-only for parameter lists</translation>
    </message>
    <message>
        <source>the drive sets this value itself</source>
        <translation>the drive sets this value itself</translation>
    </message>
</context>
<context>
    <name>ParameterProperties</name>
    <message>
        <source>stored as byte</source>
        <translation>stored as byte</translation>
    </message>
    <message>
        <source>stored as word</source>
        <translation>stored as word</translation>
    </message>
    <message>
        <source>stored as long</source>
        <translation>stored as long</translation>
    </message>
    <message>
        <source>storage width 3 (not used)</source>
        <translation>storage width 3 (not used)</translation>
    </message>
    <message>
        <source>scaling result: byte</source>
        <translation>scaling result: byte</translation>
    </message>
    <message>
        <source>scaling result: word</source>
        <translation>scaling result: word</translation>
    </message>
    <message>
        <source>scaling result: long</source>
        <translation>scaling result: long</translation>
    </message>
    <message>
        <source>scaling result: none</source>
        <translation>scaling result: none</translation>
    </message>
    <message>
        <source>lower limit variable at power on</source>
        <translation>lower limit variable at power on</translation>
    </message>
    <message>
        <source>lower limit always variable</source>
        <translation>lower limit always variable</translation>
    </message>
    <message>
        <source>lower limit type 3 (not used)</source>
        <translation>lower limit type 3 (not used)</translation>
    </message>
    <message>
        <source>upper limit variable at power on</source>
        <translation>upper limit variable at power on</translation>
    </message>
    <message>
        <source>upper limit always variable</source>
        <translation>upper limit always variable</translation>
    </message>
    <message>
        <source>upper limit type 3 (not used)</source>
        <translation>upper limit type 3 (not used)</translation>
    </message>
    <message>
        <source>no enter</source>
        <translation>no enter</translation>
    </message>
    <message>
        <source>enter with dot</source>
        <translation>enter with dot</translation>
    </message>
    <message>
        <source>enter without dot</source>
        <translation>enter without dot</translation>
    </message>
    <message>
        <source>enter mode 3 (not used)</source>
        <translation>enter mode 3 (not used)</translation>
    </message>
    <message>
        <source>no display filtering</source>
        <translation>no display filtering</translation>
    </message>
    <message>
        <source>display filtering: time slot</source>
        <translation>display filtering: time slot</translation>
    </message>
    <message>
        <source>display filtering: filter</source>
        <translation>display filtering: filter</translation>
    </message>
    <message>
        <source>display filtering 3 (not used)</source>
        <translation>display filtering 3 (not used)</translation>
    </message>
    <message>
        <source>signed</source>
        <translation>signed</translation>
    </message>
    <message>
        <source>set-programmable</source>
        <translation>set-programmable</translation>
    </message>
    <message>
        <source>writable while the active set is displayed</source>
        <translation>writable while the active set is displayed</translation>
    </message>
    <message>
        <source>scaled in the background</source>
        <translation>scaled in the background</translation>
    </message>
    <message>
        <source>variable default value</source>
        <translation>variable default value</translation>
    </message>
    <message>
        <source>default loaded only for a new device</source>
        <translation>default loaded only for a new device</translation>
    </message>
    <message>
        <source>not permitted as process data or for surveillance</source>
        <translation>not permitted as process data or for surveillance</translation>
    </message>
    <message>
        <source>encoder parameter</source>
        <translation>encoder parameter</translation>
    </message>
    <message>
        <source>system parameter</source>
        <translation>system parameter</translation>
    </message>
    <message>
        <source>variable display scaling</source>
        <translation>variable display scaling</translation>
    </message>
    <message>
        <source>visible on the display</source>
        <translation>visible on the display</translation>
    </message>
    <message>
        <source>writable on the display</source>
        <translation>writable on the display</translation>
    </message>
    <message>
        <source>visible in COMBIVIS</source>
        <translation>visible in COMBIVIS</translation>
    </message>
    <message>
        <source>writable via COMBIVIS</source>
        <translation>writable via COMBIVIS</translation>
    </message>
    <message>
        <source>rotating count</source>
        <translation>rotating count</translation>
    </message>
    <message>
        <source>changed by the inverter</source>
        <translation>changed by the inverter</translation>
    </message>
    <message>
        <source>value without plaintext not displayed</source>
        <translation>value without plaintext not displayed</translation>
    </message>
    <message>
        <source>configuration flag set (indirect configuration parameters, offline time base µs)</source>
        <translation>configuration flag set (indirect configuration parameters, offline time base µs)</translation>
    </message>
    <message>
        <source>write always: written by upload and download</source>
        <translation>write always: written by upload and download</translation>
    </message>
    <message>
        <source>write only: not read by upload, written by download</source>
        <translation>write only: not read by upload, written by download</translation>
    </message>
    <message>
        <source>excluded from the complete parameter list</source>
        <translation>excluded from the complete parameter list</translation>
    </message>
    <message>
        <source>not permitted as CP parameter</source>
        <translation>not permitted as CP parameter</translation>
    </message>
    <message>
        <source>decimal value of plaintexts suppressed</source>
        <translation>decimal value of plaintexts suppressed</translation>
    </message>
    <message>
        <source>read-only for up/download lists: not written by download</source>
        <translation>read-only for up/download lists: not written by download</translation>
    </message>
    <message>
        <source>protected</source>
        <translation>protected</translation>
    </message>
    <message>
        <source>writable only at nop or error</source>
        <translation>writable only at nop or error</translation>
    </message>
    <message>
        <source>default not loaded while invisible</source>
        <translation>default not loaded while invisible</translation>
    </message>
    <message>
        <source>shows the state at &apos;NOP&apos; and &apos;LS&apos;</source>
        <translation>shows the state at &apos;NOP&apos; and &apos;LS&apos;</translation>
    </message>
    <message>
        <source>indirectly addressed</source>
        <translation>indirectly addressed</translation>
    </message>
    <message>
        <source>not set-programmable for &apos;foc synchron&apos;</source>
        <translation>not set-programmable for &apos;foc synchron&apos;</translation>
    </message>
    <message>
        <source>read level: %1</source>
        <translation>read level: %1</translation>
    </message>
    <message>
        <source>write level: %1</source>
        <translation>write level: %1</translation>
    </message>
    <message numerus="yes">
        <source>visible for inverter type(s) %1</source>
        <translation>
            <numerusform>visible for inverter type %1</numerusform>
            <numerusform>visible for inverter types %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>writable for inverter type(s) %1</source>
        <translation>
            <numerusform>writable for inverter type %1</numerusform>
            <numerusform>writable for inverter types %1</numerusform>
        </translation>
    </message>
    <message>
        <source>read-only via COMBIVIS</source>
        <translation>read-only via COMBIVIS</translation>
    </message>
    <message>
        <source>properties 2: free bit %1 set</source>
        <translation>properties 2: free bit %1 set</translation>
    </message>
</context>
<context>
    <name>ParameterTable</name>
    <message numerus="yes">
        <source>%n group(s)</source>
        <translation>
            <numerusform>%n group</numerusform>
            <numerusform>%n groups</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s)</source>
        <translation>
            <numerusform>%n parameter</numerusform>
            <numerusform>%n parameters</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (sets 0-7)</source>
        <translation>%1 (sets 0-7)</translation>
    </message>
    <message>
        <source>parameter</source>
        <translation>parameter</translation>
    </message>
    <message>
        <source>name</source>
        <translation>name</translation>
    </message>
    <message>
        <source>value</source>
        <translation>value</translation>
    </message>
    <message>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <source>max</source>
        <translation>max</translation>
    </message>
    <message>
        <source>default</source>
        <translation>default</translation>
    </message>
    <message>
        <source>unit</source>
        <translation>unit</translation>
    </message>
    <message>
        <source>connection: %1 (%2)</source>
        <translation>connection: %1 (%2)</translation>
    </message>
    <message>
        <source>group</source>
        <translation>group</translation>
    </message>
    <message>
        <source>address</source>
        <translation>address</translation>
    </message>
    <message>
        <source>parameters</source>
        <translation>parameters</translation>
    </message>
    <message>
        <source>set</source>
        <translation>set</translation>
    </message>
    <message numerus="yes">
        <source>%n difference(s)</source>
        <translation>
            <numerusform>%n difference</numerusform>
            <numerusform>%n differences</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) on both sides</source>
        <translation>
            <numerusform>%n parameter on both sides</numerusform>
            <numerusform>%n parameters on both sides</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>PasswordLevel</name>
    <message>
        <source>CP read only</source>
        <translation>CP read only</translation>
    </message>
    <message>
        <source>CP read/write</source>
        <translation>CP read/write</translation>
    </message>
    <message>
        <source>CP service</source>
        <translation>CP service</translation>
    </message>
    <message>
        <source>Application</source>
        <translation>Application</translation>
    </message>
    <message>
        <source>Drive mode</source>
        <translation>Drive mode</translation>
    </message>
    <message>
        <source>unused</source>
        <translation>unused</translation>
    </message>
    <message>
        <source>Security</source>
        <translation>Security</translation>
    </message>
    <message>
        <source>Supervisor</source>
        <translation>Supervisor</translation>
    </message>
</context>
<context>
    <name>Plaintexts</name>
    <message>
        <source>definition %1</source>
        <translation>definition %1</translation>
    </message>
    <message>
        <source>%1 (no plaintext in %2)</source>
        <translation>%1 (no plaintext in %2)</translation>
    </message>
    <message>
        <source>%1 (no plaintext)</source>
        <translation>%1 (no plaintext)</translation>
    </message>
    <message>
        <source>other bits %1</source>
        <translation>other bits %1</translation>
    </message>
    <message>
        <source>this parameter has no plaintexts</source>
        <translation>this parameter has no plaintexts</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a plaintext of this parameter; allowed: %2</source>
        <translation>&apos;%1&apos; is not a plaintext of this parameter; allowed: %2</translation>
    </message>
    <message>
        <source>no text given; allowed: %1</source>
        <translation>no text given; allowed: %1</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has an empty text between &apos;|&apos;</source>
        <translation>&apos;%1&apos; has an empty text between &apos;|&apos;</translation>
    </message>
    <message>
        <source>&apos;%1&apos; and &apos;%2&apos; are texts of the same definition</source>
        <translation>&apos;%1&apos; and &apos;%2&apos; are texts of the same definition</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a text of several definitions: give one text for each definition, in order (%2)</source>
        <translation>&apos;%1&apos; is a text of several definitions: give one text for each definition, in order (%2)</translation>
    </message>
</context>
<context>
    <name>PlantDrive</name>
    <message>
        <source>found</source>
        <translation>found</translation>
    </message>
    <message>
        <source>saved</source>
        <translation>saved</translation>
    </message>
    <message>
        <source>equal</source>
        <translation>equal</translation>
    </message>
    <message>
        <source>different</source>
        <translation>different</translation>
    </message>
    <message>
        <source>another kind of drive</source>
        <translation>another kind of drive</translation>
    </message>
    <message>
        <source>no file</source>
        <translation>no file</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>failed</translation>
    </message>
    <message>
        <source>unreachable</source>
        <translation>unreachable</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>stopped</translation>
    </message>
    <message>
        <source>written</source>
        <translation>written</translation>
    </message>
    <message>
        <source>already equal, nothing written</source>
        <translation>already equal, nothing written</translation>
    </message>
    <message>
        <source>dry run</source>
        <translation>dry run</translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n drive(s) %2</source>
        <translation>
            <numerusform>%1 of %n drive %2</numerusform>
            <numerusform>%1 of %n drives %2</numerusform>
        </translation>
    </message>
    <message>
        <source>not: %1</source>
        <translation>not: %1</translation>
    </message>
</context>
<context>
    <name>PlantFile</name>
    <message>
        <source>an HSP5 link reaches one drive: addresses are for a DIN66019 bus, leave them out</source>
        <translation>an HSP5 link reaches one drive: addresses are for a DIN66019 bus, leave them out</translation>
    </message>
    <message>
        <source>empty: leave addresses out to search the bus for drives</source>
        <translation>empty: leave addresses out to search the bus for drives</translation>
    </message>
    <message>
        <source>drive address %1 appears twice</source>
        <translation>drive address %1 appears twice</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is also the name of links[%2]: each link needs a name of its own</source>
        <translation>&apos;%1&apos; is also the name of links[%2]: each link needs a name of its own</translation>
    </message>
    <message>
        <source>unknown protocol &apos;%1&apos;: use hsp5, din66019ii or din66019</source>
        <translation>unknown protocol &apos;%1&apos;: use hsp5, din66019ii or din66019</translation>
    </message>
    <message>
        <source>%1, expected &apos;%2&apos;: not a DriveDesk plant file</source>
        <translation>%1, expected &apos;%2&apos;: not a DriveDesk plant file</translation>
    </message>
    <message>
        <source>not a string</source>
        <translation>not a string</translation>
    </message>
    <message>
        <source>%1 is a newer format than this DriveDesk reads (version %2); a newer DriveDesk reads it</source>
        <translation>%1 is a newer format than this DriveDesk reads (version %2); a newer DriveDesk reads it</translation>
    </message>
    <message>
        <source>empty: a link needs a name</source>
        <translation>empty: a link needs a name</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is longer than %2 characters</source>
        <translation>&apos;%1&apos; is longer than %2 characters</translation>
    </message>
    <message>
        <source>&apos;%1&apos; cannot be part of a file name: use letters a-z, digits, &apos;-&apos;, &apos;_&apos; and &apos;.&apos;, starting with a letter or digit</source>
        <translation>&apos;%1&apos; cannot be part of a file name: use letters a-z, digits, &apos;-&apos;, &apos;_&apos; and &apos;.&apos;, starting with a letter or digit</translation>
    </message>
    <message>
        <source>&apos;%1&apos; names a device on Windows: choose another name</source>
        <translation>&apos;%1&apos; names a device on Windows: choose another name</translation>
    </message>
    <message>
        <source>%1 (line %2, column %3)</source>
        <translation>%1 (line %2, column %3)</translation>
    </message>
    <message>
        <source>not valid JSON: %1</source>
        <translation>not valid JSON: %1</translation>
    </message>
    <message>
        <source>not a DriveDesk plant file: the document is not a JSON object</source>
        <translation>not a DriveDesk plant file: the document is not a JSON object</translation>
    </message>
    <message>
        <source>%1: appears twice in one object</source>
        <translation>%1: appears twice in one object</translation>
    </message>
    <message>
        <source>empty: give the machine a name</source>
        <translation>empty: give the machine a name</translation>
    </message>
    <message>
        <source>empty: a plant has at least one link</source>
        <translation>empty: a plant has at least one link</translation>
    </message>
</context>
<context>
    <name>Reply</name>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message numerus="yes">
        <source>drive refused: %1 (after %n attempt(s))</source>
        <translation>
            <numerusform>drive refused: %1 (after %n attempt)</numerusform>
            <numerusform>drive refused: %1 (after %n attempts)</numerusform>
        </translation>
    </message>
    <message>
        <source>drive refused: %1</source>
        <translation>drive refused: %1</translation>
    </message>
    <message>
        <source>no valid answer from the drive</source>
        <translation>no valid answer from the drive</translation>
    </message>
    <message numerus="yes">
        <source>no valid answer from the drive after %n attempt(s)</source>
        <translation>
            <numerusform>no valid answer from the drive after %n attempt</numerusform>
            <numerusform>no valid answer from the drive after %n attempts</numerusform>
        </translation>
    </message>
    <message>
        <source>the connection to the drive was lost</source>
        <translation>the connection to the drive was lost</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>cancelled</translation>
    </message>
    <message>
        <source>not connected to a drive</source>
        <translation>not connected to a drive</translation>
    </message>
    <message>
        <source>this request cannot be sent</source>
        <translation>this request cannot be sent</translation>
    </message>
    <message>
        <source>sent to a group of drives or to all drives, which never answer: carried out, not confirmed</source>
        <translation>sent to a group of drives or to all drives, which never answer: carried out, not confirmed</translation>
    </message>
    <message>
        <source>the drive stopped answering</source>
        <translation>the drive stopped answering</translation>
    </message>
    <message>
        <source>the drive stopped answering: %1</source>
        <translation>the drive stopped answering: %1</translation>
    </message>
</context>
<context>
    <name>ReplyCheck</name>
    <message>
        <source>a text with the control character %1h</source>
        <translation>a text with the control character %1h</translation>
    </message>
    <message>
        <source>limits %1 .. %2: the minimum lies above the maximum</source>
        <translation>limits %1 .. %2: the minimum lies above the maximum</translation>
    </message>
    <message>
        <source>a display scaling that cannot be computed (%1)</source>
        <translation>a display scaling that cannot be computed (%1)</translation>
    </message>
    <message>
        <source>a group of %1 parameters numbered 0 to %2</source>
        <translation>a group of %1 parameters numbered 0 to %2</translation>
    </message>
    <message>
        <source>%1 lies outside the limits %2 .. %3</source>
        <translation>%1 lies outside the limits %2 .. %3</translation>
    </message>
</context>
<context>
    <name>RunJournal</name>
    <message>
        <source>Drive &gt; Journal Every Write off writes without it</source>
        <translation>Drive &gt; Journal Every Write off writes without it</translation>
    </message>
</context>
<context>
    <name>SavedFile</name>
    <message>
        <source>cannot write &apos;%1&apos;: %2</source>
        <translation>cannot write &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <source>cannot save &apos;%1&apos;: %2</source>
        <translation>cannot save &apos;%1&apos;: %2</translation>
    </message>
</context>
<context>
    <name>ScopeChannel</name>
    <message>
        <source>Channel %1</source>
        <translation>Channel %1</translation>
    </message>
    <message>
        <source>%1 (set %2)</source>
        <translation>%1 (set %2)</translation>
    </message>
</context>
<context>
    <name>ScopeCsv</name>
    <message>
        <source>there is no channel %1</source>
        <translation>there is no channel %1</translation>
    </message>
    <message>
        <source>the export was cancelled</source>
        <translation>the export was cancelled</translation>
    </message>
    <message>
        <source>cannot write the CSV: %1</source>
        <translation>cannot write the CSV: %1</translation>
    </message>
    <message>
        <source>cannot write &apos;%1&apos;: %2</source>
        <translation>cannot write &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <source>cannot save &apos;%1&apos;: %2</source>
        <translation>cannot save &apos;%1&apos;: %2</translation>
    </message>
</context>
<context>
    <name>ScopeCsvReader</name>
    <message>
        <source>cannot read &apos;%1&apos;: %2</source>
        <translation>cannot read &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a scope CSV export: its first column is not &quot;Time [ms]&quot;</source>
        <translation>&apos;%1&apos; is not a scope CSV export: its first column is not &quot;Time [ms]&quot;</translation>
    </message>
    <message>
        <source>&apos;%1&apos;, line %2 has %3 fields, the header %4</source>
        <translation>&apos;%1&apos;, line %2 has %3 fields, the header %4</translation>
    </message>
    <message>
        <source>&apos;%1&apos;, line %2: &quot;%3&quot; in column &quot;%4&quot; is not a number</source>
        <translation>&apos;%1&apos;, line %2: &quot;%3&quot; in column &quot;%4&quot; is not a number</translation>
    </message>
    <message>
        <source>&apos;%1&apos;, line %2: the time %3 ms is earlier than the line&apos;s before</source>
        <translation>&apos;%1&apos;, line %2: the time %3 ms is earlier than the line&apos;s before</translation>
    </message>
</context>
<context>
    <name>ScopeFile</name>
    <message>
        <source>cannot read &apos;%1&apos;: %2</source>
        <translation>cannot read &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is damaged: %2</source>
        <translation>&apos;%1&apos; is damaged: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a DriveDesk scope file</source>
        <translation>&apos;%1&apos; is not a DriveDesk scope file</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is in scope file format %2 of a newer DriveDesk; this version reads format %3</source>
        <translation>&apos;%1&apos; is in scope file format %2 of a newer DriveDesk; this version reads format %3</translation>
    </message>
    <message>
        <source>its header cannot be %1 bytes long</source>
        <translation>its header cannot be %1 bytes long</translation>
    </message>
    <message>
        <source>its header is cut short</source>
        <translation>its header is cut short</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has a damaged header: %2</source>
        <translation>&apos;%1&apos; has a damaged header: %2</translation>
    </message>
    <message>
        <source>sample %1 is earlier than the one before it</source>
        <translation>sample %1 is earlier than the one before it</translation>
    </message>
    <message numerus="yes">
        <source>&apos;%1&apos; ends in an incomplete sample (%n byte(s)), which was left out: the recording was cut off</source>
        <translation>
            <numerusform>&apos;%1&apos; ends in an incomplete sample (%n byte), which was left out: the recording was cut off</numerusform>
            <numerusform>&apos;%1&apos; ends in an incomplete sample (%n bytes), which was left out: the recording was cut off</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ScopeFileFormat</name>
    <message>
        <source>not JSON (%1 at byte %2)</source>
        <translation>not JSON (%1 at byte %2)</translation>
    </message>
    <message>
        <source>not a JSON object</source>
        <translation>not a JSON object</translation>
    </message>
    <message>
        <source>expected a date and time (ISO 8601) or null</source>
        <translation>expected a date and time (ISO 8601) or null</translation>
    </message>
    <message>
        <source>expected %1 channels, found %2</source>
        <translation>expected %1 channels, found %2</translation>
    </message>
    <message>
        <source>expected an object</source>
        <translation>expected an object</translation>
    </message>
</context>
<context>
    <name>ScopeFileWriter</name>
    <message>
        <source>cannot write &apos;%1&apos;: %2</source>
        <translation>cannot write &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <source>no recording file is open</source>
        <translation>no recording file is open</translation>
    </message>
    <message>
        <source>cannot write &apos;%1&apos;: a sample is earlier than the one before it</source>
        <translation>cannot write &apos;%1&apos;: a sample is earlier than the one before it</translation>
    </message>
</context>
<context>
    <name>ScopeMathDefinition</name>
    <message>
        <source>a derivative needs samples at two different times</source>
        <translation>a derivative needs samples at two different times</translation>
    </message>
    <message>
        <source>a difference or a sum reads two channels</source>
        <translation>a difference or a sum reads two channels</translation>
    </message>
    <message>
        <source>a derivative, an integral or a moving average reads one channel</source>
        <translation>a derivative, an integral or a moving average reads one channel</translation>
    </message>
    <message>
        <source>there is no channel %1 (1..%2)</source>
        <translation>there is no channel %1 (1..%2)</translation>
    </message>
    <message>
        <source>the window is a whole number of samples, at least 1</source>
        <translation>the window is a whole number of samples, at least 1</translation>
    </message>
    <message>
        <source>the window is a time in ms, more than 0</source>
        <translation>the window is a time in ms, more than 0</translation>
    </message>
    <message>
        <source>unknown kind &quot;%1&quot;</source>
        <translation>unknown kind &quot;%1&quot;</translation>
    </message>
    <message>
        <source>expected a number</source>
        <translation>expected a number</translation>
    </message>
    <message>
        <source>expected samples or ms</source>
        <translation>expected samples or ms</translation>
    </message>
    <message>
        <source>the units differ: %1, %2</source>
        <translation>the units differ: %1, %2</translation>
    </message>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <source>d/dt %1</source>
        <translation>d/dt %1</translation>
    </message>
    <message>
        <source>∫ %1 dt</source>
        <translation>∫ %1 dt</translation>
    </message>
    <message>
        <source>%1 − %2</source>
        <translation>%1 − %2</translation>
    </message>
    <message>
        <source>%1 + %2</source>
        <translation>%1 + %2</translation>
    </message>
    <message numerus="yes">
        <source>%1, mean of %n sample(s)</source>
        <translation>
            <numerusform>%1, mean of %n sample</numerusform>
            <numerusform>%1, mean of %n samples</numerusform>
        </translation>
    </message>
    <message>
        <source>%1, mean over %2 ms</source>
        <translation>%1, mean over %2 ms</translation>
    </message>
</context>
<context>
    <name>ScopeOverlay</name>
    <message>
        <source>%1 (overlay: %2)</source>
        <comment>a channel&apos;s title, the overlay&apos;s file</comment>
        <translation>%1 (overlay: %2)</translation>
    </message>
    <message>
        <source>the overlay %1 has no trigger (it is no single shot)</source>
        <translation>the overlay %1 has no trigger (it is no single shot)</translation>
    </message>
    <message>
        <source>the recording shown has no trigger (it is no single shot)</source>
        <translation>the recording shown has no trigger (it is no single shot)</translation>
    </message>
</context>
<context>
    <name>ScopeOverlayTraces</name>
    <message>
        <source>%1 [%2]</source>
        <comment>channel title and unit</comment>
        <translation>%1 [%2]</translation>
    </message>
</context>
<context>
    <name>ScopePollJob</name>
    <message>
        <source>This connection cannot carry scope data (service 18).</source>
        <translation>This connection cannot carry scope data (service 18).</translation>
    </message>
    <message>
        <source>The drive stopped answering: %1</source>
        <translation>The drive stopped answering: %1</translation>
    </message>
</context>
<context>
    <name>ScopePresetFile</name>
    <message>
        <source>expected a number</source>
        <translation>expected a number</translation>
    </message>
    <message>
        <source>%1 is outside %2..%3</source>
        <translation>%1 is outside %2..%3</translation>
    </message>
    <message>
        <source>%1, expected &apos;%2&apos;: not a DriveDesk scope preset</source>
        <translation>%1, expected &apos;%2&apos;: not a DriveDesk scope preset</translation>
    </message>
    <message>
        <source>not a string</source>
        <translation>not a string</translation>
    </message>
    <message>
        <source>%1 is a newer format than this DriveDesk reads (version %2); a newer DriveDesk reads it</source>
        <translation>%1 is a newer format than this DriveDesk reads (version %2); a newer DriveDesk reads it</translation>
    </message>
    <message>
        <source>expected a parameter id, &quot;off&quot; or null</source>
        <translation>expected a parameter id, &quot;off&quot; or null</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a colour: write it as #rrggbb</source>
        <translation>&apos;%1&apos; is not a colour: write it as #rrggbb</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: expected rising or falling</source>
        <translation>&apos;%1&apos;: expected rising or falling</translation>
    </message>
    <message>
        <source>channel %1</source>
        <translation>channel %1</translation>
    </message>
    <message>
        <source>channel %1&apos;s %2</source>
        <translation>channel %1&apos;s %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a parameter id: write it as group.number (ru.03), a hexadecimal address (0203h), with @set where it is read from another set (op.11@2), or off</source>
        <translation>&apos;%1&apos; is not a parameter id: write it as group.number (ru.03), a hexadecimal address (0203h), with @set where it is read from another set (op.11@2), or off</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: the set after @ is 0..%2, e.g. op.11@2</source>
        <translation>&apos;%1&apos;: the set after @ is 0..%2, e.g. op.11@2</translation>
    </message>
    <message>
        <source>%1 (line %2, column %3)</source>
        <translation>%1 (line %2, column %3)</translation>
    </message>
    <message>
        <source>not JSON: %1</source>
        <translation>not JSON: %1</translation>
    </message>
    <message>
        <source>not a DriveDesk scope preset: the document is not a JSON object</source>
        <translation>not a DriveDesk scope preset: the document is not a JSON object</translation>
    </message>
    <message>
        <source>%1: appears twice in one object</source>
        <translation>%1: appears twice in one object</translation>
    </message>
    <message>
        <source>give the preset a name of 1 to %1 characters</source>
        <translation>give the preset a name of 1 to %1 characters</translation>
    </message>
    <message>
        <source>expected %1 channels, found %2</source>
        <translation>expected %1 channels, found %2</translation>
    </message>
    <message>
        <source>preset file &apos;%1&apos;: %2</source>
        <translation>preset file &apos;%1&apos;: %2</translation>
    </message>
</context>
<context>
    <name>ScopePresetLibrary</name>
    <message>
        <source>cannot make the folder &apos;%1&apos; for the presets</source>
        <translation>cannot make the folder &apos;%1&apos; for the presets</translation>
    </message>
</context>
<context>
    <name>ScopeSpectrum</name>
    <message>
        <source>too few samples for a spectrum: %1 in the window, at least %2 needed</source>
        <translation>too few samples for a spectrum: %1 in the window, at least %2 needed</translation>
    </message>
    <message>
        <source>the samples span no time: all %1 are in one ms</source>
        <translation>the samples span no time: all %1 are in one ms</translation>
    </message>
    <message>
        <source>not enough memory for a spectrum</source>
        <translation>not enough memory for a spectrum</translation>
    </message>
</context>
<context>
    <name>ScopeSpectrumPlot</name>
    <message>
        <source>Frequency [Hz]</source>
        <translation>Frequency [Hz]</translation>
    </message>
    <message>
        <source>Amplitude</source>
        <translation>Amplitude</translation>
    </message>
    <message>
        <source>Frequency</source>
        <translation>Frequency</translation>
    </message>
    <message>
        <source>The highest peaks, the highest first</source>
        <translation>The highest peaks, the highest first</translation>
    </message>
    <message>
        <source>Amplitude [%1]</source>
        <translation>Amplitude [%1]</translation>
    </message>
    <message>
        <source>Hz</source>
        <translation>Hz</translation>
    </message>
</context>
<context>
    <name>ScopeTraces</name>
    <message>
        <source>%1 [%2]</source>
        <comment>channel title and unit</comment>
        <translation>%1 [%2]</translation>
    </message>
    <message>
        <source>Value [%1]</source>
        <comment>the units of the channels on the shared axis</comment>
        <translation>Value [%1]</translation>
    </message>
</context>
<context>
    <name>SetList</name>
    <message>
        <source>no set</source>
        <translation>no set</translation>
    </message>
    <message>
        <source>all sets</source>
        <translation>all sets</translation>
    </message>
    <message>
        <source>set %1</source>
        <translation>set %1</translation>
    </message>
    <message>
        <source>sets %1</source>
        <translation>sets %1</translation>
    </message>
    <message>
        <source>active set</source>
        <translation>active set</translation>
    </message>
    <message>
        <source>set of the set pointer</source>
        <translation>set of the set pointer</translation>
    </message>
    <message>
        <source>set selection %1</source>
        <translation>set selection %1</translation>
    </message>
</context>
<context>
    <name>Telegram</name>
    <message>
        <source>unspecified</source>
        <translation>unspecified</translation>
    </message>
    <message>
        <source>status interrogation</source>
        <translation>status interrogation</translation>
    </message>
    <message>
        <source>DIN66019 value</source>
        <translation>DIN66019 value</translation>
    </message>
    <message>
        <source>value (set mask)</source>
        <translation>value (set mask)</translation>
    </message>
    <message>
        <source>value (standard set)</source>
        <translation>value (standard set)</translation>
    </message>
    <message>
        <source>limits</source>
        <translation>limits</translation>
    </message>
    <message>
        <source>default value</source>
        <translation>default value</translation>
    </message>
    <message>
        <source>properties</source>
        <translation>properties</translation>
    </message>
    <message>
        <source>display scaling</source>
        <translation>display scaling</translation>
    </message>
    <message>
        <source>parameter name</source>
        <translation>parameter name</translation>
    </message>
    <message>
        <source>plaintext indices</source>
        <translation>plaintext indices</translation>
    </message>
    <message>
        <source>display plaintext</source>
        <translation>display plaintext</translation>
    </message>
    <message>
        <source>plaintext</source>
        <translation>plaintext</translation>
    </message>
    <message>
        <source>group properties</source>
        <translation>group properties</translation>
    </message>
    <message>
        <source>group name</source>
        <translation>group name</translation>
    </message>
    <message>
        <source>plaintext definition</source>
        <translation>plaintext definition</translation>
    </message>
    <message>
        <source>field-bus function</source>
        <translation>field-bus function</translation>
    </message>
    <message>
        <source>value (subindex)</source>
        <translation>value (subindex)</translation>
    </message>
    <message>
        <source>process data 2x32</source>
        <translation>process data 2x32</translation>
    </message>
    <message>
        <source>process data 4x16</source>
        <translation>process data 4x16</translation>
    </message>
    <message>
        <source>scope</source>
        <translation>scope</translation>
    </message>
    <message>
        <source>process data type 4</source>
        <translation>process data type 4</translation>
    </message>
    <message>
        <source>process data type 5</source>
        <translation>process data type 5</translation>
    </message>
    <message>
        <source>scope record</source>
        <translation>scope record</translation>
    </message>
    <message>
        <source>default (set mask)</source>
        <translation>default (set mask)</translation>
    </message>
    <message>
        <source>default (standard set)</source>
        <translation>default (standard set)</translation>
    </message>
    <message>
        <source>duplex process data 2x32</source>
        <translation>duplex process data 2x32</translation>
    </message>
    <message>
        <source>duplex process data 4x16</source>
        <translation>duplex process data 4x16</translation>
    </message>
    <message>
        <source>duplex process data + parameter</source>
        <translation>duplex process data + parameter</translation>
    </message>
    <message>
        <source>duplex process data type 4</source>
        <translation>duplex process data type 4</translation>
    </message>
    <message>
        <source>duplex process data type 5</source>
        <translation>duplex process data type 5</translation>
    </message>
    <message>
        <source>duplex process data type 6</source>
        <translation>duplex process data type 6</translation>
    </message>
    <message>
        <source>service %1</source>
        <translation>service %1</translation>
    </message>
</context>
<context>
    <name>TelegramText</name>
    <message>
        <source> (subindex %1)</source>
        <translation> (subindex %1)</translation>
    </message>
    <message>
        <source>write %1 = %2%3</source>
        <translation>write %1 = %2%3</translation>
    </message>
    <message>
        <source>read %1%2</source>
        <translation>read %1%2</translation>
    </message>
    <message>
        <source>reset %1 to its default%2</source>
        <translation>reset %1 to its default%2</translation>
    </message>
    <message>
        <source>check whether %1 holds its default%2</source>
        <translation>check whether %1 holds its default%2</translation>
    </message>
    <message>
        <source>read the limits of %1</source>
        <translation>read the limits of %1</translation>
    </message>
    <message>
        <source>read the default of %1</source>
        <translation>read the default of %1</translation>
    </message>
    <message>
        <source>read the properties of %1</source>
        <translation>read the properties of %1</translation>
    </message>
    <message>
        <source>read the display scaling of %1</source>
        <translation>read the display scaling of %1</translation>
    </message>
    <message>
        <source>read the name of group %1</source>
        <translation>read the name of group %1</translation>
    </message>
    <message>
        <source>read the name of %1</source>
        <translation>read the name of %1</translation>
    </message>
    <message>
        <source>read the plaintext indices of %1</source>
        <translation>read the plaintext indices of %1</translation>
    </message>
    <message>
        <source>read the properties of group %1</source>
        <translation>read the properties of group %1</translation>
    </message>
    <message>
        <source>read plaintext %1.%2.%3</source>
        <translation>read plaintext %1.%2.%3</translation>
    </message>
    <message>
        <source>read plaintext definition %1.%2</source>
        <translation>read plaintext definition %1.%2</translation>
    </message>
    <message>
        <source>read display plaintext %1.%2 for %3</source>
        <translation>read display plaintext %1.%2 for %3</translation>
    </message>
    <message>
        <source>write %1</source>
        <translation>write %1</translation>
    </message>
    <message>
        <source>read %1</source>
        <translation>read %1</translation>
    </message>
    <message>
        <source>write %1: %2</source>
        <translation>write %1: %2</translation>
    </message>
    <message>
        <source>read %1: %2</source>
        <translation>read %1: %2</translation>
    </message>
    <message>
        <source>written: %1 = %2%3</source>
        <translation>written: %1 = %2%3</translation>
    </message>
    <message>
        <source>%1: %2%3</source>
        <translation>%1: %2%3</translation>
    </message>
    <message>
        <source>%1 reset to its default%2</source>
        <translation>%1 reset to its default%2</translation>
    </message>
    <message>
        <source>%1 holds its default%2</source>
        <translation>%1 holds its default%2</translation>
    </message>
    <message>
        <source>limits of %1: %2 .. %3</source>
        <translation>limits of %1: %2 .. %3</translation>
    </message>
    <message>
        <source>default of %1: %2</source>
        <translation>default of %1: %2</translation>
    </message>
    <message>
        <source>properties of %1: %2, %3</source>
        <translation>properties of %1: %2, %3</translation>
    </message>
    <message>
        <source>display scaling of %1: divisor %2, multiplier %3, offset %4, flags %5</source>
        <translation>display scaling of %1: divisor %2, multiplier %3, offset %4, flags %5</translation>
    </message>
    <message>
        <source>name of group %1: &quot;%2&quot;</source>
        <translation>name of group %1: &quot;%2&quot;</translation>
    </message>
    <message>
        <source>name of %1: &quot;%2&quot;</source>
        <translation>name of %1: &quot;%2&quot;</translation>
    </message>
    <message>
        <source>plaintext indices of %1: display %2 (%3), COMBIVIS %4 (%5)</source>
        <translation>plaintext indices of %1: display %2 (%3), COMBIVIS %4 (%5)</translation>
    </message>
    <message>
        <source>group %1: id %2, order %3, highest number %4, count %5</source>
        <translation>group %1: id %2, order %3, highest number %4, count %5</translation>
    </message>
    <message>
        <source>plaintext %1.%2.%3: %4 = &quot;%5&quot;</source>
        <translation>plaintext %1.%2.%3: %4 = &quot;%5&quot;</translation>
    </message>
    <message>
        <source>plaintext definition %1.%2: mask %3, count %4, &quot;%5&quot;</source>
        <translation>plaintext definition %1.%2: mask %3, count %4, &quot;%5&quot;</translation>
    </message>
    <message>
        <source>scope at %1 ms: %2, %3, %4, %5</source>
        <translation>scope at %1 ms: %2, %3, %4, %5</translation>
    </message>
    <message>
        <source>%1: done</source>
        <translation>%1: done</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>to drive %1: %2</source>
        <translation>to drive %1: %2</translation>
    </message>
    <message>
        <source>answer to no open request: %1</source>
        <translation>answer to no open request: %1</translation>
    </message>
    <message>
        <source>answer to no open request: %1, %2</source>
        <translation>answer to no open request: %1, %2</translation>
    </message>
    <message>
        <source>%1 refused: %2</source>
        <translation>%1 refused: %2</translation>
    </message>
</context>
<context>
    <name>TrafficFile</name>
    <message>
        <source>Cannot save the telegrams to %1: %2</source>
        <translation>Cannot save the telegrams to %1: %2</translation>
    </message>
    <message>
        <source>no file name given</source>
        <translation>no file name given</translation>
    </message>
</context>
<context>
    <name>TrafficFormat</name>
    <message>
        <source>Time</source>
        <translation>Time</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>Direction</translation>
    </message>
    <message>
        <source>Bytes</source>
        <translation>Bytes</translation>
    </message>
    <message>
        <source>Characters</source>
        <translation>Characters</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>Meaning</translation>
    </message>
    <message>
        <source>→ drive</source>
        <translation>→ drive</translation>
    </message>
    <message>
        <source>← drive</source>
        <translation>← drive</translation>
    </message>
    <message>
        <source>error</source>
        <translation>error</translation>
    </message>
    <message>
        <source>inverter request: %1</source>
        <translation>inverter request: %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>UploadResult</name>
    <message>
        <source>the upload was cancelled; nothing was saved</source>
        <translation>the upload was cancelled; nothing was saved</translation>
    </message>
    <message>
        <source>no answer</source>
        <translation>no answer</translation>
    </message>
    <message>
        <source>the drive could not be read to the end (%1); nothing was saved</source>
        <translation>the drive could not be read to the end (%1); nothing was saved</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) of the drive could not be read; nothing was saved</source>
        <translation>
            <numerusform>%n parameter of the drive could not be read; nothing was saved</numerusform>
            <numerusform>%n parameters of the drive could not be read; nothing was saved</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1 %2: %3</source>
        <translation>%1 %2: %3</translation>
    </message>
    <message numerus="yes">
        <source>no value read for set(s) %1</source>
        <translation>
            <numerusform>no value read for set %1</numerusform>
            <numerusform>no value read for sets %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ValueChangeText</name>
    <message>
        <source>the drive&apos;s answer cannot be its value: %1</source>
        <translation>the drive&apos;s answer cannot be its value: %1</translation>
    </message>
</context>
<context>
    <name>WholeFile</name>
    <message>
        <source>cannot read &apos;%1&apos;: %2</source>
        <translation>cannot read &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is too large (%2 bytes, at most %3)</source>
        <translation>&apos;%1&apos; is too large (%2 bytes, at most %3)</translation>
    </message>
    <message>
        <source>cannot read &apos;%1&apos;: it is a folder, not a file</source>
        <translation>cannot read &apos;%1&apos;: it is a folder, not a file</translation>
    </message>
    <message>
        <source>cannot read &apos;%1&apos;: it is not a regular file but a device or a pipe, whose reading may never end</source>
        <translation>cannot read &apos;%1&apos;: it is not a regular file but a device or a pipe, whose reading may never end</translation>
    </message>
</context>
</TS>
