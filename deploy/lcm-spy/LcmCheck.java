// Checks that LCM's own Java tools decode envdesign's traffic with our types jar.
//
//   java -cp lcm.jar:jchart2d.jar:envdesign_lcmtypes.jar:. LcmCheck spy URL SECONDS CHANNEL...
//     starts lcm-spy (lcm.spy.Spy, what Debian's wrapper runs) on URL, lets it listen, and
//     checks from its channel table that each CHANNEL was received and decoded by a type of
//     the jar with no decode error. Needs a display (xvfb-run).
//   java -cp lcm.jar:envdesign_lcmtypes.jar:. LcmCheck log FILE
//     decodes every ENVDESIGN_ event of an lcm-logger file through lcm-spy's type database
//     and prints "CHANNEL TYPE COUNT" lines; fails on an event it cannot decode.
// Exit code 0: all decoded; 1: something was not.

import java.io.ByteArrayInputStream;
import java.io.DataInputStream;
import java.io.EOFException;
import java.lang.reflect.Field;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import lcm.logging.Log;
import lcm.spy.ChannelData;
import lcm.spy.LCMTypeDatabase;
import lcm.spy.Spy;

public class LcmCheck {
    public static void main(String[] args) throws Exception {
        if (args.length >= 3 && args[0].equals("spy"))
            System.exit(spy(args[1], Double.parseDouble(args[2]), List.of(args).subList(3, args.length)));
        if (args.length == 2 && args[0].equals("log"))
            System.exit(log(args[1]));
        System.err.println("usage: LcmCheck spy URL SECONDS CHANNEL... | LcmCheck log FILE");
        System.exit(2);
    }

    static int spy(String url, double seconds, List<String> channels) throws Exception {
        Spy spy = new Spy(url);
        Thread.sleep((long) (seconds * 1000));
        Field field = Spy.class.getDeclaredField("channelList");
        field.setAccessible(true);
        List<ChannelData> rows;
        synchronized (spy) {
            @SuppressWarnings("unchecked")
            List<ChannelData> list = (List<ChannelData>) field.get(spy);
            rows = new ArrayList<>(list);
        }
        int failures = 0;
        for (String channel : channels) {
            ChannelData row = rows.stream().filter(r -> r.name.equals(channel)).findFirst().orElse(null);
            if (row == null) {
                System.out.println(channel + ": not received");
                ++failures;
                continue;
            }
            boolean ok = row.cls != null && row.nerrors == 0 && row.last != null;
            System.out.println(channel + ": " + (row.cls == null ? "UNDECODED" : row.cls.getName())
                               + ", " + row.nreceived + " received, " + row.nerrors + " errors"
                               + (ok ? "" : "  <-- FAILED"));
            failures += ok ? 0 : 1;
        }
        return failures == 0 ? 0 : 1;
    }

    static int log(String file) throws Exception {
        LCMTypeDatabase types = new LCMTypeDatabase();
        Log log = new Log(file, "r");
        Map<String, Integer> counts = new TreeMap<>();
        int undecodable = 0;
        while (true) {
            Log.Event event;
            try {
                event = log.readNext();
            } catch (EOFException end) {
                break;
            }
            if (!event.channel.startsWith("ENVDESIGN_"))
                continue;
            String type = decode(types, event.data);
            if (type == null) {
                System.out.println(event.channel + ": undecodable event " + event.eventNumber);
                ++undecodable;
                continue;
            }
            counts.merge(event.channel + " " + type, 1, Integer::sum);
        }
        for (Map.Entry<String, Integer> e : counts.entrySet())
            System.out.println(e.getKey() + " " + e.getValue());
        return undecodable == 0 ? 0 : 1;
    }

    // The type's simple name, or null if no type has the message's fingerprint or the
    // message does not decode as it.
    static String decode(LCMTypeDatabase types, byte[] data) {
        try {
            long fingerprint = new DataInputStream(new ByteArrayInputStream(data)).readLong();
            Class<?> cls = types.getClassByFingerprint(fingerprint);
            if (cls == null)
                return null;
            cls.getConstructor(byte[].class).newInstance((Object) data);
            return cls.getSimpleName();
        } catch (Exception e) {
            return null;
        }
    }
}
